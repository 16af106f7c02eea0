"""The description format: one item per line, `KIND key=value ...`
(a line ending in & goes on on the next), comments from # to the end of a
line. Values are numbers, vectors
(`x,y,z`), point lists (`x,y,z;x,y,z;...`) or words. Every value is
checked here (finite numbers, the right count of components, known keys),
and an error names the line.
"""
import math
import re


class LayoutError(Exception):
    def __init__(self, line, message):
        super().__init__(message)
        self.line = line


# Decimal or exponent notation only: float() alone would also take 1_000,
# digits of other scripts and infinity.
NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")


def number(text):
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is not None and not math.isfinite(value):
        raise ValueError("expected a finite number, got '%s'" % text)
    if value is None or not NUMBER.fullmatch(text):
        raise ValueError("expected a number, got '%s'" % text)
    return value


def integer(text):
    value = number(text)
    if value != int(value):
        raise ValueError("expected a whole number, got '%s'" % text)
    return int(value)


def vector(count):
    def parse(text):
        parts = text.split(",")
        if len(parts) != count:
            raise ValueError("expected %d comma-separated numbers, got '%s'" % (count, text))
        return tuple(number(p) for p in parts)
    return parse


def points(text):
    pts = [vector(3)(p) for p in text.split(";")]
    if len(pts) < 2:
        raise ValueError("expected at least two points x,y,z;x,y,z, got '%s'" % text)
    return pts


def word(*choices):
    def parse(text):
        if text not in choices:
            raise ValueError("expected one of %s, got '%s'" % (", ".join(choices), text))
        return text
    return parse


def name(text):
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", text):
        raise ValueError("a name is a letter then letters, digits or _, got '%s'" % text)
    return text


def hook_angle(text):
    if text == "none":
        return None
    value = number(text)
    if value not in (90.0, 135.0, 180.0):
        raise ValueError("a hook is 90, 135, 180 or none, got '%s'" % text)
    return value


# The keys every clump item takes (their defaults from `defaults` lines).
COMMON = {"diameter": number, "smoothness": number, "spacing": number, "type": integer,
          "density": number, "name": name}
HOOKS = {"hook_start": hook_angle, "hook_end": hook_angle, "hook_length": number,
         "hook_towards": vector(3), "bend": number}
KINDS = {
    "defaults": dict(COMMON),
    "output": {"decimals": integer, "ntry": integer},
    "box": {"lo": vector(3), "hi": vector(3)},
    "bar": dict(COMMON, **HOOKS, **{"from": vector(3), "to": vector(3)}),
    "polyline": dict(COMMON, **HOOKS, points=points),
    "stirrups": dict(COMMON, axis=word("x", "y", "z"), **{"from": number, "to": number},
                     every=number, centre=vector(2), width=number, height=number, bend=number),
    "cage": dict(COMMON, axis=word("x", "y", "z"), **{"from": number, "to": number},
                 centre=vector(2), width=number, height=number, cover=number,
                 bars_bottom=integer, bars_top=integer, hook=hook_angle, hook_length=number,
                 bend=number, stirrup_diameter=number, stirrup_bend=number, every=number,
                 stirrups_from=number, stirrups_to=number),
    "mesh": dict(COMMON, corner=vector(3), a=vector(3), b=vector(3), every_a=number,
                 every_b=number, diameter_b=number),
    "fibres": dict(COMMON, lo=vector(3), hi=vector(3), length=number, count=integer,
                   fraction=number, orientation=word("isotropic", "plane"),
                   normal=word("x", "y", "z"), seed=integer, apart=word("yes", "no"),
                   tries=integer, templates=word("one", "each")),
}
REQUIRED = {
    "box": ("lo", "hi"),
    "bar": ("from", "to"),
    "polyline": ("points",),
    "stirrups": ("axis", "from", "to", "every", "centre", "width", "height"),
    "cage": ("axis", "from", "to", "centre", "width", "height", "cover", "every"),
    "mesh": ("corner", "a", "b", "every_a", "every_b"),
    "fibres": ("lo", "hi", "length", "seed"),
}


class Item:
    def __init__(self, kind, line, values):
        self.kind, self.line, self.values = kind, line, values

    def get(self, key, default=None):
        return self.values.get(key, default)

    def error(self, message):
        raise LayoutError(self.line, message)


def parse_line(text, line):
    words = text.split()
    kind = words[0]
    if kind not in KINDS:
        raise LayoutError(line, "unknown item '%s' (known: %s)" % (kind, ", ".join(sorted(KINDS))))
    spec = KINDS[kind]
    values = {}
    for w in words[1:]:
        key, eq, raw = w.partition("=")
        if not eq or not key or not raw:
            raise LayoutError(line, "expected key=value, got '%s'" % w)
        if key not in spec:
            raise LayoutError(line, "unknown key '%s' for %s (known: %s)" % (key, kind, ", ".join(sorted(spec))))
        if key in values:
            raise LayoutError(line, "key '%s' given twice" % key)
        try:
            values[key] = spec[key](raw)
        except ValueError as e:
            raise LayoutError(line, "%s: %s" % (key, e))
    for key in REQUIRED.get(kind, ()):
        if key not in values:
            raise LayoutError(line, "%s needs %s=" % (kind, key))
    if "count" in values and "fraction" in values:
        raise LayoutError(line, "give count= or fraction=, not both")
    if kind == "fibres" and "count" not in values and "fraction" not in values:
        raise LayoutError(line, "fibres need count= or fraction=")
    if "spacing" in values and "smoothness" in values:
        raise LayoutError(line, "give spacing= or smoothness=, not both")
    return Item(kind, line, values)


def logical_lines(text):
    """(first line number, text) of each item: comments and blank lines
    dropped, a line ending in & continued on the next (as in LAMMPS)."""
    first, parts = None, []
    for number_, raw in enumerate(text.splitlines(), start=1):
        content = raw.split("#", 1)[0].strip()
        if not content:
            continue
        if first is None:
            first = number_
        more = content.endswith("&")
        parts.append(content[:-1] if more else content)
        if not more:
            yield first, " ".join(parts)
            first, parts = None, []
    if parts:
        raise LayoutError(first, "the item ends with & but no line follows")


def parse(text):
    """Items of the description, `defaults` merged into every later item."""
    items = []
    defaults = {}
    for number_, content in logical_lines(text):
        item = parse_line(content, number_)
        if item.kind == "defaults":
            if "name" in item.values:
                raise LayoutError(number_, "name= is for one item, not for defaults")
            if "spacing" in item.values:
                defaults.pop("smoothness", None)
            if "smoothness" in item.values:
                defaults.pop("spacing", None)
            defaults.update(item.values)
            continue
        if item.kind in ("output", "box"):
            items.append(item)
            continue
        merged = dict(defaults)
        if "spacing" in item.values or "smoothness" in item.values:
            merged.pop("spacing", None)
            merged.pop("smoothness", None)
        merged.update(item.values)
        item.values = merged
        items.append(item)
    return items
