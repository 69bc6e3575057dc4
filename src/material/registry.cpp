// material registry: filled in by the materials work
