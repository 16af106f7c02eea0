#!/usr/bin/env python3
"""No test runs mpirun as its own command: each goes through a script that
sources test_env.sh (its own Open MPI session directory; the shared /tmp
tree lets concurrent runs break each other), e.g. mpi_run.sh.

    mpirun_own_session.py CTEST BUILD_DIR
"""
import json
import os
import subprocess
import sys

ctest, build = sys.argv[1], sys.argv[2]
out = subprocess.run([ctest, "--show-only=json-v1"], cwd=build, check=True,
                     capture_output=True, text=True).stdout
tests = json.loads(out)["tests"]
bad = [t["name"] for t in tests
       if any(os.path.basename(w) in ("mpirun", "mpiexec", "orterun") for w in t.get("command", []))]
for name in bad[:10]:
    print(f"{name}: runs mpirun itself (use tests/scripts/mpi_run.sh)")
if bad or not tests:
    print(f"FAIL: {len(bad)} of {len(tests)} tests run mpirun without test_env.sh")
    sys.exit(1)
print(f"PASS: none of {len(tests)} tests runs mpirun without test_env.sh")
