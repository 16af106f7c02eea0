#!/usr/bin/env python3
"""The counts tests/README.md states, against the build's tests and the code.

Usage: readme_counts.py README TOTALS_H BUILD_DIR CTEST [--mutate]

Checks, in README:
  * "`Suite.Name` (N)": N is the number of GoogleTest tests of the core
    (the ctest names Suite.Name that `CTEST -N` lists in BUILD_DIR);
  * every "`PATTERN` (N" whose PATTERN has a `*` (e.g. `stability_*` (34,
    `BoundariesAdd.*` (2)): N is the number of ctest names it matches; a
    pattern that matches no test of this build (a host not built) is
    skipped, and said so;
  * "f_ID[1..N]": N is kOutputSize in TOTALS_H (the length of the fix's
    global vector);
  * every unit test it names (`Suite.Name`, no wildcard) is one of the
    build's.
Prints one line per count, then "PASS: ..." or "FAIL: ...". --mutate adds
one to the unit test count read from README first: the check's own proof
that it sees a wrong count.
"""
import fnmatch
import re
import subprocess
import sys


def ctest_names(build, ctest):
    out = subprocess.run([ctest, "-N"], cwd=build, capture_output=True, text=True, check=True)
    return re.findall(r"^\s*Test\s+#\d+: (\S+)\s*$", out.stdout, re.M)


def main(argv):
    mutate = "--mutate" in argv
    args = [a for a in argv[1:] if a != "--mutate"]
    if len(args) != 4:
        print(__doc__)
        return 2
    readme_path, totals_path, build, ctest = args
    readme = open(readme_path).read()
    names = ctest_names(build, ctest)
    unit = [n for n in names if re.fullmatch(r"[A-Z]\w*\.\w+(/\w+)*", n)]
    size = re.search(r"constexpr\s+int\s+kOutputSize\s*=\s*(\d+)\s*;", open(totals_path).read())
    wrong, checked = [], 0

    def check(what, stated, actual):
        nonlocal checked
        checked += 1
        line = f"{what}: README says {stated}, "
        if stated == actual:
            print(line + "and so it is")
        else:
            print(line + f"there are {actual}")
            wrong.append(what)

    stated_unit = re.search(r"`Suite\.Name` \((\d+)\)", readme)
    stated_output = re.search(r"f_ID\[1\.\.(\d+)\]", readme)
    if not names or not unit or not size or not stated_unit or not stated_output:
        print("FAIL: no tests listed in the build, or no unit test count or f_ID range in the "
              "README, or no kOutputSize in the header")
        return 1
    check("unit tests (`Suite.Name`)", int(stated_unit.group(1)) + (1 if mutate else 0), len(unit))
    check("output vector (f_ID[1..N])", int(stated_output.group(1)), int(size.group(1)))
    for pattern, stated in re.findall(r"`([^`\s]*\*[^`\s]*)` \((\d+)[,:)]", readme):
        matched = [n for n in names if fnmatch.fnmatchcase(n, pattern)]
        if not matched:
            print(f"`{pattern}`: README says {stated}; no test of this build matches: skipped")
            continue
        check(f"`{pattern}`", int(stated), len(matched))
    unit_set = set(unit)
    for name in sorted(set(re.findall(r"`([A-Z]\w*\.[A-Z]\w*)`", readme)) - {"Suite.Name"}):
        checked += 1
        if name not in unit_set:
            print(f"`{name}`: README names it, no such unit test")
            wrong.append(f"`{name}`")
    if wrong:
        print(f"FAIL: {len(wrong)} of {checked} counts and names in {readme_path} are wrong: "
              + ", ".join(wrong))
        return 1
    print(f"PASS: the {checked} counts and unit test names in {readme_path} are those of the build and the code")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
