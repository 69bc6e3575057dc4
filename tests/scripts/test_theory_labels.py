"""Equation labels of docs/theory/: the promise docs/theory.md makes, checked.

Every label such as (C1) or (K1a) is defined by exactly one note of docs/theory/, with a letter
that the table "label letters | note" of docs/theory.md gives to that note, so a bare label in a
code comment is unambiguous. Every citation `(note.md, X9)` (also `docs/theory/note.md, X9`,
`note.md (X9)`, `note.md, eqs. X3-X5`) in docs/, src/, tests/, bench/, scripts/ and examples/
names a label its note has.

A label is defined where the note states it:
- `**(X9)**` or `**(X9) Title.**` opening a paragraph, or a bold span holding it
  (`**Seeded values (I0).**`), or right after a bold span (`**Load** (M11)`);
- `(X9)` opening a line (`(M1)  I1 = tr C`);
- `(X9)` closing a line of a displayed formula, two spaces or more after it.
Notes outside docs/theory/ (verification, studies) also name labels in their prose ("Asserted
(IS4): ..."); a citation of such a note needs the label written in it in parentheses.

Run by CTest (label unit) with Debian's python3; needs no build and runs no plisse.
"""
import re
import sys
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LABEL = r"[A-Z]+[0-9]+[a-z]?"
# Folders whose files may cite labels, and the kinds of file read there.
CITING_FOLDERS = ("docs", "src", "tests", "bench", "scripts", "examples")
CITING_SUFFIXES = {".md", ".hpp", ".cpp", ".h", ".py", ".yaml", ".txt", ".cmake", ""}

_DEFINITIONS = [
    re.compile(r"^[ \t>*-]*\*\*\((" + LABEL + r")\)", re.M),                # **(X9)** ...
    re.compile(r"\*\*[^*\n]*\((" + LABEL + r")\)[^*\n]*\*\*"),               # **Title (X9).**
    re.compile(r"\*\*[^*\n]+\*\*[ \t]*\((" + LABEL + r")\)"),                # **Title** (X9)
    re.compile(r"^\((" + LABEL + r")\)[ \t]", re.M),                         # (X9)  y = ...
    re.compile(r"[ \t]{2}\((" + LABEL + r")\)[ \t]*$", re.M),                # formula ... (X9)
]
_MENTION = re.compile(r"\((" + LABEL + r")\)|\((" + LABEL + r")[–-]|[–-](" + LABEL + r")\)")
# A citation: a note's path, then its label, possibly a range (X3-X5, (X3)–(X5)).
_CITATION = re.compile(
    r"(?P<note>[\w./-]*[\w-]\.md)\)?[,:]?[ \t]*(?:\n[ \t]*(?://+|#|\*|///)?[ \t]*)?"
    r"(?:eqs?\.[ \t]*)?\(?(?P<first>" + LABEL + r")(?![\w])"
    r"(?:\)?[ \t]*[–-][ \t]*\(?(?P<last>" + LABEL + r")(?![\w]))?")


def prefix(label):
    """The letters of a label: 'K' for K1a, 'MR' for MR6."""
    return re.match(r"[A-Z]+", label).group(0)


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def defined_labels(text):
    """{label: line of its first definition} of a note's text."""
    found = {}
    for pattern in _DEFINITIONS:
        for m in pattern.finditer(text):
            line = line_of(text, m.start(1))
            if m.group(1) not in found or line < found[m.group(1)]:
                found[m.group(1)] = line
    return found


def mentioned_labels(text):
    """Every label written in parentheses in a text, also as the end of a range."""
    return {g for m in _MENTION.finditer(text) for g in m.groups() if g}


def letter_table(theory_md):
    """{letters: note} from the table of docs/theory.md whose header is 'label letters | note'.

    A letters cell reads 'U (energy, interpolation), R (residual)': the words in parentheses
    say what the letters are for. Raises ValueError when the table is missing or gives one
    letter to two notes."""
    lines = theory_md.splitlines()
    start = next((i for i, l in enumerate(lines)
                  if re.match(r"\|\s*label letters\s*\|\s*note\s*\|", l)), None)
    if start is None:
        raise ValueError("docs/theory.md: no table '| label letters | note |'")
    table = {}
    for l in lines[start + 2:]:
        if not l.startswith("|"):
            break
        cells = [c.strip() for c in l.strip().strip("|").split("|")]
        letters_cell, note = cells[0], cells[1].strip("` ")
        for letters in re.findall(r"\b[A-Z]+\b", re.sub(r"\([^)]*\)", "", letters_cell)):
            if letters in table and table[letters] != note:
                raise ValueError(f"docs/theory.md: letter {letters} given to {table[letters]} "
                                 f"and to {note}")
            table[letters] = note
    return table


def label_problems(notes, table):
    """Problems of the theory notes' own labels. notes: {file name: text} of docs/theory/*.md.

    A label defined by two notes, a letter the table gives to another note or to none, and a
    table row naming a note that does not exist."""
    problems = []
    owner = {}
    for name in sorted(notes):
        for label, line in sorted(defined_labels(notes[name]).items(), key=lambda x: x[1]):
            letters = prefix(label)
            if label in owner:
                other, other_line = owner[label]
                problems.append(f"docs/theory/{name}:{line}: ({label}) is also defined in "
                                f"docs/theory/{other}:{other_line}")
            else:
                owner[label] = (name, line)
            if letters not in table:
                problems.append(f"docs/theory/{name}:{line}: ({label}): the letter {letters} "
                                f"is not in the table of docs/theory.md")
            elif table[letters] != name:
                problems.append(f"docs/theory/{name}:{line}: ({label}): docs/theory.md gives "
                                f"the letter {letters} to {table[letters]}")
    for letters, name in sorted(table.items()):
        if name not in notes:
            problems.append(f"docs/theory.md: the letter {letters} is given to {name}, which is "
                            f"not a note of docs/theory/")
    return problems


def citations(text):
    """[(line, note as written, label)] of the citations in a text; a range gives both ends."""
    found = []
    for m in _CITATION.finditer(text):
        for group in ("first", "last"):
            if m.group(group):
                found.append((line_of(text, m.start(group)), m.group("note"), m.group(group)))
    return found


def resolve(note, docs):
    """The key of docs ({path under docs/: text}) a cited note names, or None.

    'docs/theory/x.md', 'theory/x.md' and '../theory/x.md' name that file; a bare 'x.md' is
    the theory note of that name if there is one, else the one file of docs/ with that name."""
    path = re.sub(r"^(\.\./|\./)+", "", note)
    path = re.sub(r"^docs/", "", path)
    matches = [k for k in docs if k == path or k.endswith("/" + path)]
    if "/" not in path and "theory/" + path in matches:
        return "theory/" + path
    return matches[0] if len(matches) == 1 else None


def labels_of(key, text):
    """The labels a citation of a note may name: those a theory note defines; for another page
    (verification, studies) also those its prose writes in parentheses."""
    labels = set(defined_labels(text))
    if not key.startswith("theory/"):
        labels |= mentioned_labels(text)
    return labels


def citation_problems(files, docs):
    """Citations of labels their note does not have, or of notes docs/ does not have.

    files: {path shown in a message: text} of the citing files; docs: {path under docs/: text}
    of every page of docs/."""
    problems = []
    labels = {key: labels_of(key, text) for key, text in docs.items()}
    for path in sorted(files):
        for line, note, label in citations(files[path]):
            key = resolve(note, docs)
            if key is None:
                # A .md name that is not a page of docs/ (README.md, a paper) is no citation.
                if "/" in note and not note.lstrip("./").startswith("docs/"):
                    continue
                if not any(k.endswith(Path(note).name) for k in docs):
                    continue
                problems.append(f"{path}:{line}: ({note}, {label}): which page of docs/ is "
                                f"{note}?")
            elif label not in labels[key]:
                problems.append(f"{path}:{line}: ({note}, {label}): docs/{key} has no label "
                                f"{label}")
    return problems


def read_tree(root):
    """(theory notes, docs pages, citing files) of a source tree."""
    docs_dir = root / "docs"
    docs = {p.relative_to(docs_dir).as_posix(): p.read_text(encoding="utf-8")
            for p in sorted(docs_dir.rglob("*.md"))}
    notes = {k[len("theory/"):]: t for k, t in docs.items()
             if k.startswith("theory/") and k.count("/") == 1}
    this = Path(__file__).resolve()
    files = {}
    for folder in CITING_FOLDERS:
        for p in sorted((root / folder).rglob("*")):
            if p.is_file() and p.suffix in CITING_SUFFIXES and p.resolve() != this:
                try:
                    files[p.relative_to(root).as_posix()] = p.read_text(encoding="utf-8")
                except UnicodeDecodeError:
                    continue
    return notes, docs, files


def check_tree(root):
    """Every problem of the labels of a source tree (docs/theory.md, docs/, the citing files)."""
    notes, docs, files = read_tree(root)
    table = letter_table((root / "docs" / "theory.md").read_text(encoding="utf-8"))
    return label_problems(notes, table) + citation_problems(files, docs)


TABLE = """# Theory

| label letters | note |
|---|---|
| A (area), B (bubble) | a.md |
| C | c.md |
"""


class LetterTableTest(unittest.TestCase):
    def test_reads_letters_and_skips_what_they_are_for(self):
        self.assertEqual(letter_table(TABLE), {"A": "a.md", "B": "a.md", "C": "c.md"})

    def test_a_letter_given_to_two_notes_is_refused(self):
        with self.assertRaisesRegex(ValueError, "letter C given to c.md and to d.md"):
            letter_table(TABLE + "| C | d.md |\n")

    def test_a_page_without_the_table_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no table"):
            letter_table("# Theory\n")


class DefinitionTest(unittest.TestCase):
    def test_each_way_of_stating_a_label(self):
        text = ("**(A1)** x = 1, by (C9)\n"
                "**(A2) Area.** The area\n"
                "- **Seeded values (A3).** The seed\n"
                "**Load** (A4). The load\n"
                "(A5)  y = 2\n"
                "    z = 3                     (A6)\n"
                "(A1) and (A2) give, by (C9) of c.md:\n"
                "the sum (B7a) of (A5) and (A6) (C8)\n")
        self.assertEqual(defined_labels(text),
                         {"A1": 1, "A2": 2, "A3": 3, "A4": 4, "A5": 5, "A6": 6})


class LabelProblemsTest(unittest.TestCase):
    table = {"A": "a.md", "B": "a.md", "C": "c.md"}

    def test_labels_with_their_notes_letters_pass(self):
        notes = {"a.md": "**(A1)** x\n\n(B1)  y, by (C1)\n", "c.md": "    z = 1      (C1)\n"}
        self.assertEqual(label_problems(notes, self.table), [])

    def test_a_label_defined_by_two_notes_fails(self):
        notes = {"a.md": "**(A1)** x\n", "c.md": "**(C1)** y\n\n**(A1)** z\n"}
        problems = label_problems(notes, self.table)
        self.assertIn("docs/theory/c.md:3: (A1) is also defined in docs/theory/a.md:1", problems)

    def test_a_letter_of_another_note_fails(self):
        notes = {"a.md": "**(A1)** x\n", "c.md": "**(C1)** y\n\n**(B2)** z\n"}
        self.assertEqual(label_problems(notes, self.table),
                         ["docs/theory/c.md:3: (B2): docs/theory.md gives the letter B to a.md"])

    def test_a_letter_missing_from_the_table_fails(self):
        notes = {"a.md": "**(A1)** x\n", "c.md": "(CX1)  y\n"}
        self.assertEqual(label_problems(notes, self.table),
                         ["docs/theory/c.md:1: (CX1): the letter CX is not in the table of "
                          "docs/theory.md"])

    def test_a_table_row_without_its_note_fails(self):
        self.assertEqual(label_problems({"a.md": "**(A1)** x\n"}, self.table),
                         ["docs/theory.md: the letter C is given to c.md, "
                          "which is not a note of docs/theory/"])


class CitationTest(unittest.TestCase):
    docs = {"theory/a.md": "**(A1)** x\n\n**(A2)** y, by c.md (C3)\n",
            "theory/c.md": "**(C3)** z\n",
            "studies/s.md": "the onset, asserted (S1): it holds\n",
            "verification/a.md": "(V1)  w\n"}

    def problems(self, text):
        return citation_problems({"src/x.cpp": text}, self.docs)

    def test_the_ways_of_citing(self):
        self.assertEqual(citations("// (a.md, A1), docs/theory/a.md, A2, a.md (A1)\n"
                                   "// a.md, eqs. A1-A2 and (c.md, C3)–(C3)\n"),
                         [(1, "a.md", "A1"), (1, "docs/theory/a.md", "A2"), (1, "a.md", "A1"),
                          (2, "a.md", "A1"), (2, "a.md", "A2"), (2, "c.md", "C3"),
                          (2, "c.md", "C3")])

    def test_labels_that_exist_pass(self):
        self.assertEqual(self.problems("// (a.md, A2), (theory/c.md, C3), (s.md, S1)\n"
                                       "// (verification/a.md, V1), see README.md (A9)\n"), [])

    def test_a_dangling_citation_fails(self):
        self.assertEqual(self.problems("int x;\n// the sum (a.md, A3)\n"),
                         ["src/x.cpp:2: (a.md, A3): docs/theory/a.md has no label A3"])

    def test_a_label_the_note_only_cites_is_not_its_own(self):
        self.assertEqual(self.problems("// (a.md, C3)\n"),
                         ["src/x.cpp:1: (a.md, C3): docs/theory/a.md has no label C3"])

    def test_the_end_of_a_range_is_checked(self):
        self.assertEqual(self.problems("// (a.md, A1-A4)\n"),
                         ["src/x.cpp:1: (a.md, A4): docs/theory/a.md has no label A4"])

    def test_a_note_of_another_folder_is_read_where_named(self):
        self.assertEqual(self.problems("// (verification/a.md, A1)\n"),
                         ["src/x.cpp:1: (verification/a.md, A1): docs/verification/a.md has no "
                          "label A1"])


class TreeTest(unittest.TestCase):
    def test_the_docs_and_the_code_of_plisse(self):
        problems = check_tree(ROOT)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))


if __name__ == "__main__":
    unittest.main(verbosity=1 if sys.stdout.isatty() else 2)
