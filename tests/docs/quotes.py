#!/usr/bin/env python3
"""tests/docs/quotes.py -- every figure the docs quote from a results table is that table's value.

A quote is a Markdown link from the figure to the committed CSV it comes from, the link's title
naming the row and the column:

    [-89.33 %](results/methods.csv "method=centreDiffusion12AlphaOnly: relative_error %")

- before the colon, key=value pairs that select exactly one row (numbers compare as numbers);
- after it, the column, and "%" when the CSV holds a fraction quoted as a percentage.

The figure (the first number in the link's text) must be the CSV's value rounded to the digits
quoted. Lines of the CSV that start with '#' (its command and commit) are skipped. Scans README.md,
doc/*.md, tutorials/*/README.md, validation/*/README.md and validation/*/results/README.md; prints a
PASS/FAIL line per document with quotes and one for the count.

    tests/docs/quotes.py [PROJECT_DIR]
"""
import csv
import glob
import os
import re
import sys

LINK = re.compile(r'\[([^\]]*?)\]\(([^)\s]+\.csv)\s+"([^"]*)"\)')
NUMBER = re.compile(r'[-+\u2212]?\d+(?:\.(\d+))?(?:[eE][-+]?\d+)?')


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def same(a, b):
    try:
        return float(a) == float(b)
    except ValueError:
        return a == b


def check_quote(doc, text, target, title):
    """None if the quote holds, else what is wrong"""
    path = os.path.normpath(os.path.join(os.path.dirname(doc), target))
    if not os.path.isfile(path):
        return f"{target}: no such file"
    if ":" not in title:
        return f'title "{title}" has no "selectors: column"'
    selectors, column = title.rsplit(":", 1)
    parts = column.split()
    if not parts:
        return f'title "{title}" names no column'
    column, percent = parts[0], "%" in parts[1:]
    rows = read_rows(path)
    for sel in selectors.split():
        if "=" not in sel:
            return f'selector "{sel}" is not key=value'
        k, v = sel.split("=", 1)
        rows = [r for r in rows if k in r and same(r[k], v)]
    if len(rows) != 1:
        return f'"{selectors.strip()}" selects {len(rows)} rows of {target}, not one'
    if column not in rows[0]:
        return f"{target} has no column {column}"
    m = NUMBER.search(text)
    if not m:
        return f'no number in "{text}"'
    quoted = float(m.group(0).replace("\u2212", "-"))
    digits = len(m.group(1) or "")
    value = float(rows[0][column]) * (100 if percent else 1)
    if abs(round(value, digits) - quoted) > 0.5 * 10 ** -digits + 1e-12 * abs(value):
        return f'"{text}" against {column} = {rows[0][column]} ({value:.{digits + 2}f}{" %" if percent else ""}) in {target}'
    return None


def main(top):
    docs = [os.path.join(top, "README.md")]
    for pattern in ("doc/*.md", "tutorials/*/README.md", "validation/*/README.md", "validation/*/results/README.md"):
        docs += sorted(glob.glob(os.path.join(top, pattern)))
    total = bad = 0
    for doc in docs:
        # code spans and blocks are examples, not quotes
        text = re.sub(r"```.*?```", "", open(doc, encoding="utf-8").read(), flags=re.S)
        text = re.sub(r"`[^`\n]*`", "", text)
        quotes = LINK.findall(text)
        if not quotes:
            continue
        errors = [e for e in (check_quote(doc, *q) for q in quotes) if e]
        total += len(quotes)
        bad += len(errors)
        rel = os.path.relpath(doc, top)
        if errors:
            print(f"FAIL: {rel}: {len(errors)} of {len(quotes)} quoted figures differ from their CSV")
            for e in errors:
                print(f"    {e}")
        else:
            print(f"PASS: {rel}: {len(quotes)} quoted figures are their CSV's values")
    print(("PASS: " if total else "FAIL: ") + f"{total} figures quoted from committed CSVs ({bad} wrong)")
    return 1 if bad or not total else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")))
