#!/usr/bin/env python3
"""The regrowth policy table of docs/design.md against the header it lists.

Usage: policy_table.py HEADER DESIGN_MD [--mutate NAME]

Every `constexpr` constant of HEADER must have one row entry in the table
under "**Regrowth policy.**" with the same value, and every name in the
table must be in HEADER. Prints one line per difference, then "PASS: ..."
or "FAIL: ...". --mutate NAME doubles NAME's value as read from HEADER
first: the check's own proof that it sees a difference.
"""
import re
import sys


def header_constants(text):
    found = {}
    for name, value in re.findall(
            r"constexpr\s+[\w:]+\s+(k\w+)\s*=\s*([^;]+);", text):
        found[name] = float(value.strip().rstrip("uUlLfF"))
    return found


def table_constants(text):
    start = text.find("**Regrowth policy.**")
    if start < 0:
        return None
    rows = {}
    in_table = False
    for line in text[start:].splitlines():
        if line.startswith("|"):
            in_table = True
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            names = re.findall(r"`(k\w+)`", cells[0])
            if not names:
                continue
            values = [v.strip() for v in cells[1].split(",")]
            if len(values) != len(names):
                rows.setdefault("(row)", []).append(line)
                continue
            for name, value in zip(names, values):
                rows.setdefault(name, []).append(value)
        elif in_table:
            break
    return rows


def main(argv):
    if len(argv) not in (3, 5) or (len(argv) == 5 and argv[3] != "--mutate"):
        print(__doc__)
        return 2
    header = header_constants(open(argv[1]).read())
    if len(argv) == 5:
        header[argv[4]] *= 2
    table = table_constants(open(argv[2]).read())
    if not header or table is None:
        print("FAIL: no constants in the header or no policy table in the design page")
        return 1
    wrong = []
    for line in table.pop("(row)", []):
        wrong.append("a row whose names and values do not pair: " + line)
    for name, value in sorted(header.items()):
        listed = table.get(name, [])
        if len(listed) != 1:
            wrong.append(f"{name}: listed {len(listed)} times in the table")
            continue
        try:
            same = float(listed[0]) == value
        except ValueError:
            same = False
        if not same:
            wrong.append(f"{name}: header {value:g}, table {listed[0]}")
    for name in sorted(set(table) - set(header)):
        wrong.append(f"{name}: in the table, not in the header")
    for line in wrong:
        print(line)
    if wrong:
        print(f"FAIL: {len(wrong)} differences between the header and the table")
        return 1
    print(f"PASS: the table lists the header's {len(header)} constants with their values")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
