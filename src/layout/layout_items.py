"""Items of the description turned into clumps: bars, polylines, stirrups,
cages and meshes (fibres: layout_fibres.py). A clump is one chain of equal
spheres (a bar, one stirrup, one fibre), written as one molecule or one
multisphere template.
"""
import math
import re

import layout_paths as P
import layout_spacing as S

AXES = {"x": (0, 1, 2), "y": (1, 0, 2), "z": (2, 0, 1)}    # axis, then the section's u, v
HOOK_LENGTH = {90.0: 12.0, 135.0: 6.0, 180.0: 4.0}    # straight leg after the bend, in bar diameters
MAX_SPHERES = 10 ** 7    # per clump, per repeat and per item: beyond it a typo, not a scene


class Clump:
    def __init__(self, name, line, radius, atom_type, density, centres):
        self.name, self.line, self.radius = name, line, radius
        self.type, self.density, self.centres = atom_type, density, centres


class Chain:
    """How one item's chains are made: radius, type, density, the spacing
    rule; and what it chose, for the summary."""

    def __init__(self, item, diameter_key="diameter"):
        self.item = item
        d = item.get(diameter_key)
        if d is None:
            item.error("%s needs %s=" % (item.kind, diameter_key))
        if d <= 0.0:
            item.error("%s must be > 0, got %g" % (diameter_key, d))
        self.radius = 0.5 * d
        self.type = item.get("type", 1)
        if self.type < 1:
            item.error("type must be >= 1, got %d" % self.type)
        self.density = item.get("density", 7800.0)
        if self.density <= 0.0:
            item.error("density must be > 0, got %g" % self.density)
        self.spacing = item.get("spacing")
        self.smoothness = item.get("smoothness", 0.05 if self.spacing is None else None)
        if self.spacing is not None and not 0.0 < self.spacing < 2.0 * self.radius:
            item.error("spacing must be > 0 and < the diameter %g (the spheres must overlap), got %g"
                       % (2.0 * self.radius, self.spacing))
        if self.smoothness is not None and not 0.0 < self.smoothness < 1.0:
            item.error("smoothness must be > 0 and < 1, got %g" % self.smoothness)
        self.used = []    # actual intervals
        self.ripples = []

    def bend_radius(self, key="bend"):
        """Centre-line radius of the bends: mandrel radius + bar radius."""
        mandrel = self.item.get(key, 4.0 * self.radius)
        if mandrel < self.radius:
            self.item.error("%s: the mandrel radius %g is tighter than the bar (radius %g)"
                            % (key, mandrel, self.radius))
        return mandrel + self.radius

    def step(self, pieces):
        if self.spacing is not None:
            return self.spacing
        step = S.straight_step(self.radius, self.smoothness)
        for p in pieces:
            if isinstance(p, P.Arc):
                step = min(step, S.bend_step(self.radius, p.radius, self.smoothness))
        return step

    def chain(self, pieces, closed):
        step = self.step(pieces)
        length = P.total_length(pieces)
        if step * MAX_SPHERES < length:    # also a step that underflowed to 0
            self.item.error("a clump %g long would need more than %d spheres at a step of %g: "
                            "raise smoothness or spacing" % (length, MAX_SPHERES, step))
        centres, actual = P.sample(pieces, step, closed)
        self.used.append(actual)
        ripple = S.straight_ripple(self.radius, actual)
        for p in pieces:
            if isinstance(p, P.Arc):
                ripple = max(ripple, S.bend_ripple(self.radius, p.radius, S.arc_chord(p.radius, actual)))
        self.ripples.append(ripple)
        return centres

    def repeated(self, count, spheres):
        """Refuses count clumps of this many spheres each beyond MAX_SPHERES
        in all, before they are made."""
        if count * spheres > MAX_SPHERES:
            self.item.error("%d clumps of %d spheres would be more than %d spheres in one item: "
                            "raise smoothness or spacing, or repeat less" % (count, spheres, MAX_SPHERES))

    def clump(self, name, centres):
        """name: the kind and line (bar_l5, stirrup_l7_3), or the item's
        name= in place of the kind and line (hoops_3; a cage's beam_stirrup_3)."""
        given = self.item.get("name")
        if given and self.item.kind == "cage":
            name = given + "_" + re.sub(r"_l\d+", "", name)
        elif given:
            name = re.sub(r"^[a-z]+_l\d+", given, name)
        return Clump(name, self.item.line, self.radius, self.type, self.density, centres)

    def summary(self, what, count, spheres):
        rule = ("spacing %.6g asked" % self.spacing if self.spacing is not None else
                "smoothness %.6g asked" % self.smoothness)
        return ("line %d %s: %d %s, %d spheres of radius %.6g, spacing %.6g to %.6g (%s), "
                "largest ripple %.4g of the radius"
                % (self.item.line, self.item.kind, count, what, spheres, self.radius,
                   min(self.used), max(self.used), rule, max(self.ripples)))


def with_hooks(chain, pieces, start_angle, end_angle, towards_start, towards_end):
    item = chain.item
    if start_angle is None and end_angle is None:
        return pieces
    radius = chain.bend_radius()
    d = 2.0 * chain.radius

    def leg(angle):
        length = item.get("hook_length", HOOK_LENGTH[angle] * d)
        if length < 0.0:
            item.error("hook_length must be >= 0, got %g" % length)
        return length

    try:
        if end_angle is not None:
            last = pieces[-1]
            pieces = pieces + P.hook(last.point(1.0), last.end_tangent(), towards_end, radius, end_angle,
                                     leg(end_angle))
        if start_angle is not None:
            back = P.reversed_pieces(pieces)
            last = back[-1]
            back = back + P.hook(last.point(1.0), last.end_tangent(), towards_start, radius, start_angle,
                                 leg(start_angle))
            pieces = P.reversed_pieces(back)
    except ValueError as e:
        item.error(str(e))
    return pieces


def build_bar(item):
    chain = Chain(item)
    a, b = item.get("from"), item.get("to")
    if a == b:
        item.error("zero-length bar: from and to are the same point")
    pieces = [P.Line(a, b)]
    towards = item.get("hook_towards", (0.0, 0.0, 1.0))
    pieces = with_hooks(chain, pieces, item.get("hook_start"), item.get("hook_end"), towards, towards)
    centres = chain.chain(pieces, closed=False)
    return [chain.clump("bar_l%d" % item.line, centres)], chain.summary("bar", 1, len(centres))


def build_polyline(item):
    chain = Chain(item)
    pts = item.get("points")
    try:
        pieces = P.fillet_polyline(pts, chain.bend_radius())
    except ValueError as e:
        item.error(str(e))
    towards = item.get("hook_towards", (0.0, 0.0, 1.0))
    pieces = with_hooks(chain, pieces, item.get("hook_start"), item.get("hook_end"), towards, towards)
    centres = chain.chain(pieces, closed=False)
    return [chain.clump("polyline_l%d" % item.line, centres)], chain.summary("bar", 1, len(centres))


def section_point(axis, along, u, v):
    p = [0.0, 0.0, 0.0]
    a, iu, iv = AXES[axis]
    p[a], p[iu], p[iv] = along, u, v
    return tuple(p)


def positions(item, first, last, every, keys=("from", "to", "every")):
    """first, first + every, ... up to last; keys: the names of the three
    in the description, for the messages."""
    if every <= 0.0:
        item.error("%s must be > 0, got %g" % (keys[2], every))
    if last < first:
        item.error("%s (%g) must not be below %s (%g)" % (keys[1], last, keys[0], first))
    if (last - first) / every > MAX_SPHERES:
        item.error("%s %g repeats more than %d times between %g and %g"
                   % (keys[2], every, MAX_SPHERES, first, last))
    n = int(math.floor((last - first) / every * (1.0 + 1e-12))) + 1
    return [first + k * every for k in range(n)]


def stirrup_loop(chain, axis, along, cu, cv, width, height, key):
    """One closed stirrup (outer width x height) in the section at `along`."""
    hw, hh = 0.5 * width - chain.radius, 0.5 * height - chain.radius
    radius = chain.bend_radius(key)
    if hw < radius or hh < radius:
        chain.item.error("a stirrup %g x %g is too small for its bends (centre-line radius %g)"
                         % (width, height, radius))
    corners = [(cu, cv - hh), (cu + hw, cv - hh), (cu + hw, cv + hh), (cu - hw, cv + hh),
               (cu - hw, cv - hh), (cu, cv - hh)]
    pts = [section_point(axis, along, u, v) for u, v in corners]
    pieces = P.fillet_polyline(pts, radius)
    return chain.chain(pieces, closed=True)


def build_stirrups(item):
    chain = Chain(item)
    axis = item.get("axis")
    cu, cv = item.get("centre")
    clumps = []
    planes = positions(item, item.get("from"), item.get("to"), item.get("every"))
    for k, x in enumerate(planes):
        centres = stirrup_loop(chain, axis, x, cu, cv, item.get("width"), item.get("height"), "bend")
        chain.repeated(len(planes), len(centres))
        clumps.append(chain.clump("stirrup_l%d_%d" % (item.line, k + 1), centres))
    return clumps, chain.summary("stirrups", len(clumps), sum(len(c.centres) for c in clumps))


def cage_bar_positions(item, hw, hh, stirrup_bend, rs, rb):
    """Section positions (u, v) of the longitudinal bars relative to the
    centre: corner bars touching the stirrup's inner corner (on its
    diagonal when the corner's inner radius holds the bar, else on both
    legs), the others touching the bottom or top leg, evenly between."""
    mandrel = stirrup_bend - rs    # inner radius of the stirrup's corner
    cu, cv = hw - stirrup_bend, hh - stirrup_bend    # corner arc centre (+, + corner)
    if mandrel >= rb:
        off = (mandrel - rb) / math.sqrt(2.0)
    else:
        off = mandrel - rb
    corner_u, corner_v = cu + off, cv + off
    leg_v = hh - rs - rb
    bars = []
    for side, count in ((-1.0, item.get("bars_bottom", 2)), (1.0, item.get("bars_top", 2))):
        if count < 2:
            item.error("bars_bottom and bars_top must be >= 2 (the corner bars), got %d" % count)
        if count > 2 and 2.0 * corner_u / (count - 1) < 2.0 * rb:
            item.error("%d bars of diameter %g do not fit side by side in the stirrup"
                       % (count, 2.0 * rb))
        for k in range(count):
            if k == 0 or k == count - 1:
                u, v = (-corner_u if k == 0 else corner_u), side * corner_v
            else:
                u, v = -corner_u + 2.0 * corner_u * k / (count - 1), side * leg_v
            bars.append((u, v, side))
    return bars


def build_cage(item):
    bars = Chain(item)
    if item.get("stirrup_diameter") is None:
        item.error("cage needs stirrup_diameter=")
    stirrups = Chain(item, "stirrup_diameter")
    axis = item.get("axis")
    cu, cv = item.get("centre")
    cover = item.get("cover")
    width, height = item.get("width") - 2.0 * cover, item.get("height") - 2.0 * cover
    if cover < 0.0 or width <= 0.0 or height <= 0.0:
        item.error("cover %g leaves no room in a %g x %g section" % (cover, item.get("width"), item.get("height")))
    first, last = item.get("from"), item.get("to")
    if last <= first:
        item.error("zero-length cage: to (%g) must be above from (%g)" % (last, first))
    clumps = []
    s_first, s_last = item.get("stirrups_from", first), item.get("stirrups_to", last)
    planes = positions(item, s_first, s_last, item.get("every"), ("stirrups_from", "stirrups_to", "every"))
    for k, x in enumerate(planes):
        centres = stirrup_loop(stirrups, axis, x, cu, cv, width, height, "stirrup_bend")
        stirrups.repeated(len(planes), len(centres))
        clumps.append(stirrups.clump("stirrup_l%d_%d" % (item.line, k + 1), centres))
    n_stirrups = len(clumps)
    rs = stirrups.radius
    layout = cage_bar_positions(item, 0.5 * width - rs, 0.5 * height - rs, stirrups.bend_radius("stirrup_bend"),
                                rs, bars.radius)
    hook = item.get("hook")
    for k, (u, v, side) in enumerate(layout):
        a = section_point(axis, first, cu + u, cv + v)
        b = section_point(axis, last, cu + u, cv + v)
        inwards = section_point(axis, 0.0, 0.0, -side)    # bottom bars hook up, top bars down
        pieces = with_hooks(bars, [P.Line(a, b)], hook, hook, inwards, inwards)
        clumps.append(bars.clump("bar_l%d_%d" % (item.line, k + 1), bars.chain(pieces, closed=False)))
    n_bar_spheres = sum(len(c.centres) for c in clumps[n_stirrups:])
    return clumps, (bars.summary("longitudinal bars", len(layout), n_bar_spheres) + "\n" +
                    stirrups.summary("stirrups", n_stirrups, sum(len(c.centres) for c in clumps[:n_stirrups])))


def build_mesh(item):
    corner, a, b = item.get("corner"), item.get("a"), item.get("b")
    la, lb = P.norm(a), P.norm(b)
    if la == 0.0 or lb == 0.0:
        item.error("zero-length mesh side: a and b must be non-zero")
    normal = P.cross(a, b)
    if P.norm(normal) <= 1e-12 * la * lb:
        item.error("a and b are parallel: the mesh has no plane")
    family_a = Chain(item)
    with_b = dict(item.values)
    with_b["diameter_b"] = item.get("diameter_b", item.get("diameter"))
    family_b = Chain(type(item)(item.kind, item.line, with_b), "diameter_b")
    lift = P.scale(P.unit(normal), family_a.radius + family_b.radius)    # b bars lie on the a bars
    ua, ub = P.unit(a), P.unit(b)
    clumps = []
    counts = []
    for chain, along, across, length, key, off, tag in (
            (family_a, a, ub, lb, "every_a", (0.0, 0.0, 0.0), "a"),
            (family_b, b, ua, la, "every_b", lift, "b")):
        offsets = positions(item, 0.0, length, item.get(key), ("start", "end", key))
        counts.append(len(offsets))
        for k, t in enumerate(offsets):
            start = P.add(P.add(corner, P.scale(across, t)), off)
            centres = chain.chain([P.Line(start, P.add(start, along))], closed=False)
            chain.repeated(len(offsets), len(centres))
            clumps.append(chain.clump("mesh_l%d_%s%d" % (item.line, tag, k + 1), centres))
    na = counts[0]
    return clumps, (family_a.summary("bars along a", na, sum(len(c.centres) for c in clumps[:na])) + "\n" +
                    family_b.summary("bars along b", len(clumps) - na,
                                     sum(len(c.centres) for c in clumps[na:])))
