"""The layers of src/ as docs/architecture.md states them, checked against the includes.

docs/architecture.md, section "Layers", has a table "| folder | may include |": one row per
folder of src/, naming in backquotes the folders its files may include. Every
`#include "folder/..."` of src/**/*.hpp and src/**/*.cpp must be allowed by the row of the
including file's folder (a folder always includes itself). A folder of src/ without a row, or a
folder the table names that src/ does not have, fails too. The folders come from the table and
from src/, so a folder split in two is two rows changed in the same commit.

Run by CTest (label unit) with Debian's python3; needs no build.
"""
import re
import sys
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_HEADER = re.compile(r"^\|\s*folder\s*\|\s*may include\s*\|\s*$")
_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')


def allowed_includes(architecture_md):
    """{folder: set of folders it may include} from the table '| folder | may include |'.

    A cell names folders in backquotes; anything else in it (a dash, 'nothing') is a comment.
    Raises ValueError when the table is missing or names a folder in two rows."""
    lines = architecture_md.splitlines()
    start = next((i for i, line in enumerate(lines) if _HEADER.match(line)), None)
    if start is None:
        raise ValueError("docs/architecture.md: no table '| folder | may include |'")
    table = {}
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        names = re.findall(r"`([^`]+)`", cells[0])
        if len(names) != 1:
            raise ValueError(f"docs/architecture.md: a row without one folder: {line}")
        if names[0] in table:
            raise ValueError(f"docs/architecture.md: two rows for {names[0]}")
        table[names[0]] = set(re.findall(r"`([^`]+)`", cells[1] if len(cells) > 1 else ""))
    return table


def included_folders(text):
    """[(line, folder, path)] of the includes of a file that start with a folder name."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        m = _INCLUDE.match(line)
        if m and "/" in m.group(1):
            found.append((number, m.group(1).split("/", 1)[0], m.group(1)))
    return found


def table_problems(table, folders):
    """Folders the table names that src/ does not have, and folders of src/ without a row."""
    problems = []
    for folder in sorted(table):
        if folder not in folders:
            problems.append(f"docs/architecture.md: the row of {folder}: src/ has no folder "
                            f"{folder}")
        for target in sorted(table[folder] - folders):
            problems.append(f"docs/architecture.md: {folder} may include {target}, but src/ "
                            f"has no folder {target}")
    for folder in sorted(folders - set(table)):
        problems.append(f"src/{folder}/: no row in the include table of docs/architecture.md")
    return problems


def include_problems(files, table, folders):
    """Includes the table does not allow. files: {'src/<folder>/<file>': text}; folders: the
    folders of src/. An include whose first part is neither a folder of src/ nor one the table
    names (Eigen/Dense, petsc/...) is not one of plisse's."""
    known = folders | set(table)
    problems = []
    for path in sorted(files):
        parts = path.split("/")
        if len(parts) < 3 or parts[1] not in table:
            continue  # a file outside the folders, or of a folder without a row (said above)
        folder = parts[1]
        for line, target, included in included_folders(files[path]):
            if target == folder or target not in known or target in table[folder]:
                continue
            allowed = ", ".join(sorted(table[folder])) or "nothing"
            problems.append(f"{path}:{line}: {folder} includes \"{included}\"; "
                            f"docs/architecture.md lets {folder} include {allowed}")
    return problems


def read_tree(root):
    """(table, folders of src/, {path: text} of src/**/*.hpp and *.cpp) of a source tree."""
    src = root / "src"
    table = allowed_includes((root / "docs" / "architecture.md").read_text(encoding="utf-8"))
    folders = {p.name for p in src.iterdir() if p.is_dir()}
    files = {p.relative_to(root).as_posix(): p.read_text(encoding="utf-8")
             for p in sorted(src.rglob("*")) if p.suffix in (".hpp", ".cpp") and p.is_file()}
    return table, folders, files


def check_tree(root):
    table, folders, files = read_tree(root)
    return table_problems(table, folders) + include_problems(files, table, folders)


PAGE = """## Layers

| folder | may include |
|---|---|
| `app` | `case`, `core` |
| `case` | `core` |
| `core` | nothing |

Includes point one way.
"""


class TableTest(unittest.TestCase):
    def test_reads_each_folders_row(self):
        self.assertEqual(allowed_includes(PAGE),
                         {"app": {"case", "core"}, "case": {"core"}, "core": set()})

    def test_a_page_without_the_table_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no table"):
            allowed_includes("## Layers\n")

    def test_two_rows_of_one_folder_are_refused(self):
        with self.assertRaisesRegex(ValueError, "two rows for core"):
            allowed_includes(PAGE.replace("| `core` | nothing |",
                                          "| `core` | nothing |\n| `core` | `app` |"))

    def test_a_folder_the_table_names_but_src_lacks_fails(self):
        table = allowed_includes(PAGE.replace("| `case` | `core` |",
                                              "| `case` | `core`, `output` |"))
        self.assertEqual(table_problems(table, {"app", "case", "core"}),
                         ["docs/architecture.md: case may include output, but src/ has no "
                          "folder output"])

    def test_a_row_of_a_folder_src_lacks_fails(self):
        self.assertEqual(table_problems(allowed_includes(PAGE), {"app", "core"}),
                         ["docs/architecture.md: app may include case, but src/ has no folder "
                          "case",
                          "docs/architecture.md: the row of case: src/ has no folder case"])

    def test_a_folder_of_src_without_a_row_fails(self):
        self.assertEqual(table_problems(allowed_includes(PAGE), {"app", "case", "core", "io"}),
                         ["src/io/: no row in the include table of docs/architecture.md"])


class IncludeTest(unittest.TestCase):
    table = allowed_includes(PAGE)
    folders = {"app", "case", "core"}

    def problems(self, files):
        return include_problems(files, self.table, self.folders)

    def test_allowed_edges_pass(self):
        files = {"src/app/run.cpp": '#include "app/run.hpp"\n#include "case/case.hpp"\n'
                                    '#include <vector>\n#include "Eigen/Dense"\n',
                 "src/case/case.hpp": '#pragma once\n  #  include "core/error.hpp"\n'}
        self.assertEqual(self.problems(files), [])

    def test_a_forbidden_edge_fails_with_its_file_and_line(self):
        files = {"src/case/case.cpp": '#include "case/case.hpp"\n\n#include "app/run.hpp"\n',
                 "src/core/error.hpp": '#pragma once\n#include "case/case.hpp"\n'}
        self.assertEqual(self.problems(files),
                         ['src/case/case.cpp:3: case includes "app/run.hpp"; '
                          "docs/architecture.md lets case include core",
                          'src/core/error.hpp:2: core includes "case/case.hpp"; '
                          "docs/architecture.md lets core include nothing"])

    def test_an_include_of_a_folder_without_a_row_fails(self):
        files = {"src/case/case.cpp": '#include "schema/field.hpp"\n'}
        self.assertEqual(include_problems(files, self.table, self.folders | {"schema"}),
                         ['src/case/case.cpp:1: case includes "schema/field.hpp"; '
                          "docs/architecture.md lets case include core"])

    def test_a_commented_include_is_no_include(self):
        self.assertEqual(self.problems({"src/core/a.hpp": '// #include "app/run.hpp"\n'}), [])


class TreeTest(unittest.TestCase):
    def test_the_sources_of_plisse_follow_docs_architecture(self):
        problems = check_tree(ROOT)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))


if __name__ == "__main__":
    unittest.main(verbosity=1 if sys.stdout.isatty() else 2)
