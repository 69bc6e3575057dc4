"""Where a recorded measurement comes from: the commit of the working tree that made it.

Standard library only, so that the pages' checks (scripts/validate --check,
scripts/verification_report.py --check) run without the plotting modules.
"""
import subprocess


def tree_commit(root):
    """The short commit of HEAD in the repository at `root`, with "+changes" when src/ or tests/
    differ from it (what a run measured is then not that commit's code alone); "unknown" outside
    a git checkout."""
    done = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return "unknown"
    dirty = subprocess.run(["git", "-C", str(root), "diff", "--quiet", "HEAD", "--", "src",
                            "tests"]).returncode
    return done.stdout.strip() + ("+changes" if dirty else "")
