"""Reads what reinforce_layout wrote, for the tests: runs the command and
parses its data file (atoms by clump) and molecule files. Knows nothing of
the command's own modules: the tests check the written result."""
import os
import stat
import subprocess
import tempfile

COMMAND = os.environ.get("REINFORCE_LAYOUT", "reinforce_layout")
TIMEOUT = 60    # seconds: a run that hangs fails its test rather than the whole class's ctest entry


def run(description, *outputs):
    """Runs the command on the description text; returns (status, stdout,
    stderr, folder with description.txt and what was written)."""
    folder = tempfile.mkdtemp(prefix="layout_test.")
    path = os.path.join(folder, "description.txt")
    with open(path, "w") as f:
        f.write(description)
    args = [COMMAND, path]
    for o in outputs:
        args += ["--" + o, os.path.join(folder, {"data": "rebar.data", "molecules": "mol",
                                                 "liggghts": "templates.liggghts"}[o])]
    p = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT)
    return p.returncode, p.stdout, p.stderr, folder


def command(args, cwd, stdout=subprocess.PIPE):
    """Runs the command with these arguments in cwd; returns (status,
    stdout, or "" when it went elsewhere, stderr)."""
    p = subprocess.run([COMMAND] + args, cwd=cwd, stdout=stdout, stderr=subprocess.PIPE, text=True,
                       timeout=TIMEOUT)
    return p.returncode, p.stdout or "", p.stderr


def snapshot(folder):
    """Everything under folder: relative path -> its bytes, None for a
    folder, "special" for anything else (a pipe: reading it would block)."""
    found = {}
    for top, folders, files in os.walk(folder):
        for name in folders:
            found[os.path.relpath(os.path.join(top, name), folder)] = None
        for name in files:
            path = os.path.join(top, name)
            if stat.S_ISREG(os.lstat(path).st_mode):
                with open(path, "rb") as f:
                    found[os.path.relpath(path, folder)] = f.read()
            else:
                found[os.path.relpath(path, folder)] = "special"
    return found


def atoms(data_path):
    """(type, diameter, x, y, z) of every atom of a data file, in id order."""
    with open(data_path) as f:
        text = f.read()
    body = text.split("Atoms # sphere", 1)[1]
    rows = [line.split() for line in body.splitlines() if line.strip()]
    return [(int(r[1]), float(r[2]), float(r[4]), float(r[5]), float(r[6])) for r in rows]


def lay_out(description):
    """Centres (x, y, z) and radius of every atom, failing on a non-zero exit."""
    status, out, err, folder = run(description, "data")
    if status != 0:
        raise AssertionError("reinforce_layout failed: " + err)
    rows = atoms(os.path.join(folder, "rebar.data"))
    return [(r[2], r[3], r[4]) for r in rows], [0.5 * r[1] for r in rows], out
