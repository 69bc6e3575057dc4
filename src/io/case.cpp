// case file parser: filled in by the case-file work
