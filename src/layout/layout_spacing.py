"""Sphere spacing from a bar's radius and a smoothness.

Equal spheres of radius r whose centres are s apart along a straight axis
have an envelope that dips, between neighbours, to sqrt(r^2 - (s/2)^2)
from the axis: the ripple, relative to r, is 1 - sqrt(1 - (s/2r)^2). On a
bend of centre-line radius R the chord c between neighbours also sits
R - sqrt(R^2 - (c/2)^2) inside the arc (the sagitta), which adds to the
ripple on the outside of the bend. The step chosen keeps both within the
smoothness asked (to 1e-12 relative, by bisection).
"""
import math


def straight_ripple(radius, spacing):
    """Largest dip of the envelope between two spheres, relative to the radius."""
    half = spacing / (2.0 * radius)
    if half >= 1.0:
        return 1.0    # the spheres do not even touch: the chain is broken
    return 1.0 - math.sqrt(1.0 - half * half)


def bend_ripple(radius, bend_radius, chord):
    """Ripple on the outside of a bend: the straight dip plus the sagitta."""
    half = chord / 2.0
    sagitta = bend_radius - math.sqrt(max(0.0, bend_radius * bend_radius - half * half))
    return straight_ripple(radius, chord) + sagitta / radius


def straight_step(radius, smoothness):
    """Largest centre spacing for the smoothness on a straight bar."""
    return 2.0 * radius * math.sqrt(1.0 - (1.0 - smoothness) ** 2)


def bend_step(radius, bend_radius, smoothness):
    """Largest arc-length step on a bend of centre-line radius bend_radius."""
    lo, hi = 0.0, min(2.0 * radius, 2.0 * bend_radius)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if bend_ripple(radius, bend_radius, mid) <= smoothness:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-12 * hi:
            break
    return 2.0 * bend_radius * math.asin(min(1.0, lo / (2.0 * bend_radius)))


def arc_chord(bend_radius, arc_step):
    return 2.0 * bend_radius * math.sin(arc_step / (2.0 * bend_radius))
