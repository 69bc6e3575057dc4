"""The shared part of plisse's study scripts: running a case over a list of `--set` overrides,
reading run directories, and the figures every study draws.

    from plisse_study import runs, sweep, figures, fits, sphere, lines

- `runs`: the readers of a run directory (docs/output.md): history.csv as columns, summary.json,
  the written steps of solution.pvd, one VTU state (points, displacement, tetrahedra, Cauchy
  stress; plisse's raw appended files read by its own reader), the instabilities of log.txt and summary.json, wrinkle_spectrum.csv, a case's
  `output.wrinkles`.
- `sweep`: the `plisse run` command of one point of a sweep, run it (with its transcript, a stop
  rule or a time limit), a sweep over named points that keeps finished runs, and the folder name
  of a value of a varied key.
- `figures`: saving a figure, the deformed surface coloured by its normal deviation from the
  axisymmetric mean shape (with the rings), the same surface unrolled about the axis, and the
  quarter model's disc mirrored to the full disc.
- `lines`: a step's fields along a segment of the body (`plisse plot --line`) and the waves
  along it (count, wavelength, amplitude from its spectrum).
- `fits`: brackets around a step, slopes on logarithmic axes.
- `sphere`: the thin inflated sphere (its stretch under pressure, the outer pole), Vella et al.'s
  dimensionless pressure, the mid-surface of a spherical shell and its deflection since the
  inflated state, and the command line of the indented-shell studies.

A package rather than one grown scripts/study.py: scripts/study is one study among the others (the
YAML parameter studies and their Markdown report), and `plisse plot` and eight scripts import
these pieces; a module per concept keeps each small, lets each script import only what it uses
(matplotlib is loaded by `figures` alone) and gives each its own unit tests (tests/scripts).
The scripts run as `/usr/bin/python3 scripts/<name>.py`, so scripts/ is on the import path and
the package needs no installing. What is particular to one study (its theory, its measures, its
table) stays in that study's script.
"""
