"""The three outputs: a LAMMPS data file (atom style sphere, for
`read_data FILE add append offset 1 0 0 0 0 group rebar`), a LAMMPS
molecule file per clump (for `create_atoms ... mol` and `fix rigid`), and
LIGGGHTS `particletemplate/multisphere` sphere lists (as string variables).
Coordinates are written with full precision (the shortest text that reads
back as the same double), or rounded to `decimals` when the description
asks. Outputs (below) puts every file in place only once all are written.
"""
import errno
import math
import os
import signal
import stat
import tempfile


class OutputError(Exception):
    """An output that cannot be written: the path as given and the reason."""

    def __init__(self, path, reason):
        super().__init__("cannot write %s: %s" % (path, reason))


def reason(error):
    return error.strerror or str(error)


class Outputs:
    """The files of one run. Each is written to a temporary file in its own
    folder and renamed over its path by commit(), so a run that fails
    anywhere leaves no file created or half written: discard() removes the
    temporary files and the folders made for them. An existing path that
    is neither a file nor a folder (/dev/null, a pipe) is written in place
    by write_in_place(), after the staging: renaming over it would replace
    it."""

    def __init__(self):
        self.staged = []     # (temporary path, final path)
        self.streams = []    # (path, write)
        self.made = []       # folders made, parents first
        umask = os.umask(0)
        os.umask(umask)
        self.mode = 0o666 & ~umask    # what open() would give a new file

    def folder(self, path):
        """The folder at path, made (parents too) if missing."""
        if os.path.isdir(path):
            return
        if os.path.lexists(path):
            raise OutputError(path, os.strerror(errno.ENOTDIR))
        parent = os.path.dirname(path.rstrip(os.sep))
        if parent:
            self.folder(parent)
        blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
        try:
            os.mkdir(path)
            self.made.append(path)
        except OSError as e:
            raise OutputError(path, reason(e))
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)

    def file(self, path, write):
        """write(out) into a temporary file beside path (or, for a device
        or a pipe, into path itself by write_in_place)."""
        if not os.path.basename(path):    # "" or "folder/": no file name to rename onto
            raise OutputError(path, os.strerror(errno.EISDIR if path else errno.ENOENT))
        try:
            mode = os.stat(path).st_mode
        except FileNotFoundError:
            mode = None
        except OSError as e:
            raise OutputError(path, reason(e))
        if mode is not None and stat.S_ISDIR(mode):
            raise OutputError(path, os.strerror(errno.EISDIR))
        if mode is not None and not stat.S_ISREG(mode):
            self.streams.append((path, write))
            return
        final = os.path.realpath(path)    # through a link, as open() would write
        folder, name = os.path.split(final)
        # A signal between making the file and listing it would leave it
        # behind: none is taken in between.
        blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
        try:
            fd, temp = tempfile.mkstemp(prefix="." + name + ".", suffix=".part", dir=folder)
            self.staged.append((temp, final))
        except OSError as e:
            raise OutputError(path, reason(e))
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        try:
            os.fchmod(fd, stat.S_IMODE(mode) if mode is not None else self.mode)
            with open(fd, "w", encoding="utf-8", errors="surrogateescape") as out:
                write(out)
        except OSError as e:
            raise OutputError(path, reason(e))

    def write_in_place(self):
        """The devices and pipes, once every file is staged."""
        for path, write in self.streams:
            try:
                with open(path, "w", encoding="utf-8", errors="surrogateescape") as out:
                    write(out)
            except OSError as e:
                raise OutputError(path, reason(e))

    def commit(self):
        while self.staged:
            temp, final = self.staged[0]
            try:
                os.replace(temp, final)
            except OSError as e:
                raise OutputError(final, reason(e))
            self.staged.pop(0)
        self.made = []

    def discard(self):
        for temp, _ in self.staged:
            try:
                os.remove(temp)
            except OSError:
                pass
        for path in reversed(self.made):
            try:
                os.rmdir(path)
            except OSError:
                pass
        self.staged, self.made = [], []


def formatter(decimals):
    if decimals is None:
        return repr
    return lambda v: "%.*f" % (decimals, v)


def sphere_mass(radius, density):
    return density * 4.0 / 3.0 * math.pi * radius ** 3


def centre_of(centres):
    n = float(len(centres))
    return tuple(sum(c[k] for c in centres) / n for k in range(3))


def comments(summary):
    return "".join("# %s\n" % line for line in summary)


def write_data(out, clumps, box, summary, decimals, source):
    f = formatter(decimals)
    atoms = sum(len(c.centres) for c in clumps)
    out.write("reinforce_layout: %d rebar spheres in %d clumps from %s\n" % (atoms, len(clumps), source))
    out.write(comments(summary))
    out.write("\n%d atoms\n%d atom types\n\n" % (atoms, max(c.type for c in clumps)))
    for k, name in enumerate("xyz"):
        out.write("%s %s %slo %shi\n" % (f(box[0][k]), f(box[1][k]), name, name))
    out.write("\nAtoms # sphere\n\n")
    n = 0
    for c in clumps:
        d = f(2.0 * c.radius)
        for x, y, z in c.centres:
            n += 1
            out.write("%d %d %s %s %s %s %s\n" % (n, c.type, d, f(c.density), f(x), f(y), f(z)))


def relative(clump):
    centre = centre_of(clump.centres)
    return centre, [tuple(p[k] - centre[k] for k in range(3)) for p in clump.centres]


def write_molecule(out, c, summary, decimals):
    f = formatter(decimals)
    centre, coords = relative(c)
    mass = sphere_mass(c.radius, c.density)
    out.write("reinforce_layout: %s, %d spheres, coordinates relative to its centre\n" % (c.name, len(coords)))
    out.write("# centre %s %s %s: create_atoms 0 single %s %s %s mol ID SEED rotate 0 0 0 1 units box\n"
              % ((f(centre[0]), f(centre[1]), f(centre[2])) * 2))
    out.write("# puts it where the description laid it\n")
    out.write(comments(summary))
    out.write("\n%d atoms\n\nCoords\n\n" % len(coords))
    for i, (x, y, z) in enumerate(coords, start=1):
        out.write("%d %s %s %s\n" % (i, f(x), f(y), f(z)))
    out.write("\nTypes\n\n")
    out.write("".join("%d %d\n" % (i, c.type) for i in range(1, len(coords) + 1)))
    out.write("\nDiameters\n\n")
    out.write("".join("%d %s\n" % (i, f(2.0 * c.radius)) for i in range(1, len(coords) + 1)))
    out.write("\nMasses\n\n")
    out.write("".join("%d %r\n" % (i, mass) for i in range(1, len(coords) + 1)))


def write_molecules(outputs, folder, clumps, summary, decimals):
    """One molecule file per clump in folder, staged in outputs."""
    outputs.folder(folder)
    for c in clumps:
        outputs.file(os.path.join(folder, c.name + ".mol"),
                     lambda out, c=c: write_molecule(out, c, summary, decimals))


def write_liggghts(out, clumps, summary, decimals, ntry):
    f = formatter(decimals)
    out.write("# reinforce_layout: LIGGGHTS particletemplate/multisphere sphere lists, one string\n")
    out.write("# variable per clump, relative to the clump's centre (x y z r per sphere):\n")
    out.write("#   fix ID all particletemplate/multisphere SEED atom_type T density constant D ${NAME} type 1\n")
    out.write(comments(summary))
    for c in clumps:
        centre, coords = relative(c)
        spheres = " ".join("%s %s %s %s" % (f(x), f(y), f(z), f(c.radius)) for x, y, z in coords)
        out.write("# %s: centre %s %s %s\n" % (c.name, f(centre[0]), f(centre[1]), f(centre[2])))
        out.write('variable %s string "nspheres %d ntry %d spheres %s"\n' % (c.name, len(coords), ntry, spheres))
