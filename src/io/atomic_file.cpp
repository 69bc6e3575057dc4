// atomic file writing: filled in by the output work
