#!/usr/bin/env python3
"""Writes the scripted tool paths (sim:path waypoint files) that perform the example exercises in
resources/exercises well (*.good.path) and badly (*.bad.path). The depth for a wanted force comes
from the slope-ring model's static equilibrium (docs/scoring.md): a tool whose lowest point is d mm
below the rest surface along its normal renders R = k_s |m1| k_c d / (1 + k_c c |m1|) N (c: the
inclusion's factor, 1 outside). A "# mark-at T" line asks the runner to mark at loop time T
(palpate-cli run --mark-at T; tests/scoring reads it).

    python3 tests/scoring/make_example_scripts.py      # from the repository root
"""
import json
import math
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
RES = os.path.join(ROOT, "resources")


def load_off(path):
    words = open(path).read().split("\n")
    n, m, _ = map(int, words[1].split())
    P = [tuple(map(float, l.split())) for l in words[2:2 + n]]
    T = [tuple(map(int, l.split()))[1:] for l in words[2 + n:2 + n + m]]
    N = [[0.0, 0.0, 0.0] for _ in P]
    for a, b, c in T:
        u = [P[b][i] - P[a][i] for i in range(3)]
        v = [P[c][i] - P[a][i] for i in range(3)]
        cr = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        for k in (a, b, c):
            for i in range(3):
                N[k][i] += cr[i]
    N = [[x / math.sqrt(sum(y * y for y in nn)) for x in nn] for nn in N]
    return P, N


def add(a, b, s=1.0):
    return [a[i] + s * b[i] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def norm(a):
    l = math.sqrt(sum(x * x for x in a))
    return [x / l for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


class Script:
    def __init__(self, title):
        self.lines = ["# " + title, "# written by tests/scoring/make_example_scripts.py; t_s x_mm y_mm z_mm"]
        self.t = 0.0
        self.marks = []
        self.done_at = None

    def at(self, dt, p):
        self.t += dt
        self.lines.append("%.3f %.4f %.4f %.4f" % (self.t, p[0], p[1], p[2]))

    def mark(self):
        self.marks.append(self.t)

    def done(self):
        """The trainee finishes the examination (detect_lumps: palpate-cli run --done-at T)."""
        self.done_at = self.t

    def write(self, path):
        lines = self.lines[:2] + ["# mark-at %.3f" % t for t in self.marks]
        if self.done_at is not None:
            lines.append("# done-at %.3f" % self.done_at)
        lines += self.lines[2:]
        open(path, "w").write("\n".join(lines) + "\n")


# The radius of the tool the exercise's model touches with: ours (coherent, the default model)
# touches with a sphere of the tissue's tool radius whose centre is the device's position, so every
# point of a script is that radius further out along the normal than the sphere's lowest point.
TOOL_RADIUS_MM = [0.0]


def lift(p, n, h):
    """The device position whose sphere's lowest point is h mm out along n from p (h < 0: pressed in)."""
    return add(p, n, h + TOOL_RADIUS_MM[0])


def preset(name):
    j = json.load(open(os.path.join(RES, "presets", "tissues", name + ".json")))
    s = j["slope_ring"]
    ours = j.get("model", "coherent") in ("coherent", "palpate")
    TOOL_RADIUS_MM[0] = j.get("tissue", {}).get("tool_radius_mm", 5.0) if ours else 0.0
    return s["slopes_mm_per_n"][0], s["contact_stiffness_n_per_mm"], s["spring_stiffness_n_per_mm"]


def depth_for(force, tissue, c=1.0):
    m1, kc, ks = tissue
    return force * (1.0 + kc * c * m1) / (kc * ks * m1)


def press(s, P, N, v, depth, hold, offset=(0, 0, 0), high=15.0):
    """From `high` mm above vertex v: down to 5 mm above, press to `depth`, hold, back up."""
    p = add(P[v], offset)
    n = N[v]
    s.at(1.5, lift(p, n, high))
    s.at(0.5, lift(p, n, 5.0))
    s.at(1.0, lift(p, n, -depth))
    s.at(hold, lift(p, n, -depth))
    s.at(0.5, lift(p, n, 5.0))
    s.at(0.5, lift(p, n, high))


def exercise(name):
    return json.load(open(os.path.join(RES, "exercises", name + ".json")))


def press_targets():
    ex = exercise("press_targets")
    P, N = load_off(os.path.join(RES, ex["mesh"]))
    skin = preset("skin")
    t = [x["vertex"] for x in ex["press_targets"]["targets"]]
    good = Script("press_targets.json done well: each target pressed mid-window and held 1.6 s")
    good.at(0.0, lift(P[t[0]], N[t[0]], 15.0))
    for v, force in zip(t, [1.5, 1.5, 2.0]):
        press(good, P, N, v, depth_for(force, skin), 1.6)
    good.write(os.path.join(RES, "exercises", "press_targets.good.path"))

    bad = Script("press_targets.json done badly: first target overshot, second missed by 8 mm, third pressed too hard")
    bad.at(0.0, lift(P[t[0]], N[t[0]], 15.0))
    v = t[0]
    n = N[v]
    bad.at(1.5, lift(P[v], n, 5.0))
    bad.at(0.4, lift(P[v], n, -depth_for(3.6, skin)))  # jab: excessive force and damage
    bad.at(0.6, lift(P[v], n, -depth_for(3.6, skin)))
    bad.at(0.3, lift(P[v], n, -depth_for(1.6, skin)))
    bad.at(1.3, lift(P[v], n, -depth_for(1.6, skin)))
    bad.at(0.5, lift(P[v], n, 15.0))
    side = norm(cross(N[t[1]], [1, 0, 0]))
    press(bad, P, N, t[1], depth_for(1.5, skin), 2.0, offset=[8.0 * x for x in side])
    press(bad, P, N, t[2], depth_for(2.9, skin), 2.5)
    press(bad, P, N, t[2], depth_for(3.4, skin), 1.0, offset=[5.0 * x for x in side])
    bad.write(os.path.join(RES, "exercises", "press_targets.bad.path"))


def find_lump():
    ex = exercise("find_lump")
    P, N = load_off(os.path.join(RES, ex["mesh"]))
    liver = preset("liver")
    lump = ex["find_lump"]["inclusion"]["centre"]["vertex"]
    c = ex["find_lump"]["inclusion"]["stiffness_factor"]
    depth = 8.0  # soft tissue gives ~0.5 N there, the lump ~1.8 N
    good = Script("find_lump.json done well: gentle presses around, the stiff one marked")
    good.at(0.0, lift(P[1206], N[1206], 15.0))
    for v in [1206, 1202, 1435]:
        press(good, P, N, v, depth, 1.0)
    # On the lump: press, feel it, mark while pressing.
    n = N[lump]
    good.at(1.5, lift(P[lump], n, 15.0))
    good.at(0.5, lift(P[lump], n, 5.0))
    good.at(1.0, lift(P[lump], n, -depth))
    good.at(0.6, lift(P[lump], n, -depth))
    good.mark()
    good.at(0.4, lift(P[lump], n, -depth))
    good.at(0.5, lift(P[lump], n, 15.0))
    good.write(os.path.join(RES, "exercises", "find_lump.good.path"))

    bad = Script("find_lump.json done badly: hard presses, the lump crushed, the mark far from it")
    bad.at(0.0, lift(P[871], N[871], 15.0))
    press(bad, P, N, 871, 18.0, 1.5)
    press(bad, P, N, lump, depth_for(3.6, liver, c), 1.5)
    press(bad, P, N, 1206, 18.0, 1.5)
    n = N[871]
    bad.at(1.5, lift(P[871], n, 15.0))
    bad.at(0.5, lift(P[871], n, 5.0))
    bad.at(1.0, lift(P[871], n, -18.0))
    bad.at(3.0, lift(P[871], n, -18.0))
    bad.mark()
    bad.at(0.5, lift(P[871], n, 15.0))
    bad.write(os.path.join(RES, "exercises", "find_lump.bad.path"))


def trace():
    ex = exercise("trace")
    P, N = load_off(os.path.join(RES, ex["mesh"]))
    muscle = preset("muscle")
    path = [x["vertex"] for x in ex["trace"]["path"]]
    speed = 8.0  # mm/s along the surface

    def slide(s, depth_at, offset_mm=0.0, lift_between=None):
        for i, v in enumerate(path):
            if i == 0:
                continue
            a, b = path[i - 1], path[i]
            length = math.dist(P[a], P[b])
            steps = max(1, int(math.ceil(length / 2.0)))
            for k in range(1, steps + 1):
                f = k / steps
                p = add(P[a], sub(P[b], P[a]), f)
                n = norm(add(N[a], sub(N[b], N[a]), f))
                side = norm(cross(n, sub(P[b], P[a])))
                p = add(p, side, offset_mm)
                s.at(length / steps / speed, lift(p, n, -depth_at((i - 1 + f) / (len(path) - 1))))

    good = Script("trace.json done well: the whole line at 1 N")
    d = depth_for(1.0, muscle)
    v0 = path[0]
    good.at(0.0, lift(P[v0], N[v0], 15.0))
    good.at(1.0, lift(P[v0], N[v0], 5.0))
    good.at(1.0, lift(P[v0], N[v0], -d))
    good.at(0.3, lift(P[v0], N[v0], -d))
    slide(good, lambda f: d)
    last = path[-1]
    good.at(0.5, lift(P[last], N[last], 5.0))
    good.at(0.5, lift(P[last], N[last], 15.0))
    good.write(os.path.join(RES, "exercises", "trace.good.path"))

    bad = Script("trace.json done badly: 6 mm beside the line, contact lost in the middle, too hard at the end")
    side0 = norm(cross(N[v0], sub(P[path[1]], P[v0])))
    start = add(P[v0], side0, 6.0)
    bad.at(0.0, lift(start, N[v0], 15.0))
    bad.at(1.0, lift(start, N[v0], 5.0))
    bad.at(1.0, lift(start, N[v0], -d))

    def depth(f):
        if f < 0.3:
            return d
        if f < 0.6:
            return -2.0  # above the surface: no contact
        return depth_for(2.2, muscle)

    slide(bad, depth, offset_mm=6.0)
    bad.at(0.5, lift(P[last], N[last], 15.0))
    bad.write(os.path.join(RES, "exercises", "trace.bad.path"))


# Detect lumps (docs/scoring.md, "Lumps under the surface"): on the 50 mm sphere, a tool d mm
# below the rest surface renders R = k_s |m1| F with F = d / (1 + |m1|) on tissue (k_c = 1) and,
# over a lump whose top is z deep and whose compliance is c = 1 / contrast, the larger of that and
# (d - (1 - c) z) / (1 + c |m1|).
SPHERE_MM = 50.0


def sphere_point(theta, phi):
    u = [math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)]
    return [SPHERE_MM * x for x in u], u


def angles(p):
    x, y, z = p
    return math.acos(z / math.sqrt(x * x + y * y + z * z)), math.atan2(y, x)


def depth_over(force, tissue, lump=None):
    """The depth below the rest surface at which the tool renders `force` N, over `lump` or not."""
    m1, kc, ks = tissue
    f = force / (ks * m1)
    if lump is None or m1 * f <= lump["depth_mm"]:
        return f * (1.0 + kc * m1) / kc
    c = 1.0 / lump["contrast"]
    return f * (1.0 + kc * c * m1) / kc + (1.0 - c) * lump["depth_mm"]


def sweep_rows(s, depth, speed_mm_s, row_step_mm=8.0, step_mm=5.0):
    """Strokes along circles of latitude, row_step_mm apart, the tool `depth` mm in, from near the
    +z pole to near the -z pole: a systematic search of the whole sphere."""
    first = 0.12
    rows = []
    theta = first
    while theta < math.pi - 0.1:
        rows.append(theta)
        theta += row_step_mm / SPHERE_MM
    p, n = sphere_point(rows[0], 0.0)
    s.at(1.0, lift(p, n, 15.0))
    s.at(1.0, lift(p, n, -depth))
    for i, theta in enumerate(rows):
        circumference = 2.0 * math.pi * SPHERE_MM * math.sin(theta)
        steps = max(8, int(math.ceil(circumference / step_mm)))
        for k in range(1, steps + 1):
            p, n = sphere_point(theta, 2.0 * math.pi * k / steps)
            s.at(circumference / steps / speed_mm_s, lift(p, n, -depth))
        if i + 1 < len(rows):
            p, n = sphere_point(rows[i + 1], 0.0)
            s.at(row_step_mm / speed_mm_s, lift(p, n, -depth))
    s.at(0.5, lift(p, n, 15.0))


def palpate_at(s, point, depth, hold=1.5, mark=False):
    """Lifted 15 mm, moved over `point`, pressed in to `depth` and held still; marked 1 s into the
    hold when `mark`."""
    theta, phi = angles(point)
    p, n = sphere_point(theta, phi)
    s.at(1.0, lift(p, n, 15.0))
    s.at(0.5, lift(p, n, 3.0))
    s.at(1.0, lift(p, n, -depth))
    if mark:
        s.at(1.0, lift(p, n, -depth))
        s.mark()
        s.at(hold - 1.0, lift(p, n, -depth))
    else:
        s.at(hold, lift(p, n, -depth))
    s.at(0.5, lift(p, n, 15.0))


SEARCH_N = 0.7          # the sweeps: above the exercise's coverage force, 0.4 N
SEARCH_MM_PER_S = 60.0  # far above the 10 mm/s that is palpation
ELSEWHERE_MM = [0.0, -50.0, 0.0]  # a spot with no lump under it, pressed in doubt


def detect_lumps():
    ex = exercise("detect_lumps")
    muscle = preset("muscle")
    lumps = ex["detect_lumps"]["lumps"]
    search = depth_over(SEARCH_N, muscle)

    good = Script("detect_lumps.json done well: the whole sphere swept at 0.7 N, each lump pressed to 2.8 N and marked, a doubtful spot pressed and left")
    sweep_rows(good, search, SEARCH_MM_PER_S)
    for lump in lumps:
        palpate_at(good, lump["point_mm"], depth_over(2.8, muscle, lump), mark=True)
    palpate_at(good, ELSEWHERE_MM, depth_over(1.7, muscle))
    good.done()
    good.write(os.path.join(RES, "exercises", "detect_lumps.good.path"))

    # Presses as far as 0.9 N of tissue force: enough for the shallow lumps, not for the 8 mm one,
    # over which the surface sinks |m1| 0.9 = 5.8 mm at most.
    light = Script("detect_lumps.json pressed too lightly: swept well, every lump pressed only as deep as 0.9 N of tissue, the deep one not felt")
    sweep_rows(light, search, SEARCH_MM_PER_S)
    light_depth = depth_over(0.9, muscle)
    for k, lump in enumerate(lumps):
        palpate_at(light, lump["point_mm"], light_depth, mark=lump["depth_mm"] < 5.0)
    light.done()
    light.write(os.path.join(RES, "exercises", "detect_lumps.light.path"))

    bad = Script("detect_lumps.json done badly: three hard pokes, no search, two marks where there is no lump")
    palpate_at(bad, [0.0, 0.0, 50.0], depth_over(3.0, muscle), mark=True)
    palpate_at(bad, lumps[0]["point_mm"], depth_over(5.0, muscle, lumps[0]))
    palpate_at(bad, [0.0, -50.0, 0.0], depth_over(3.0, muscle), mark=True)
    bad.done()
    bad.write(os.path.join(RES, "exercises", "detect_lumps.bad.path"))


def no_lump():
    muscle = preset("muscle")
    search = depth_over(SEARCH_N, muscle)
    good = Script("no_lump.json done well: the whole sphere swept, two doubtful spots pressed, nothing marked")
    sweep_rows(good, search, SEARCH_MM_PER_S)
    palpate_at(good, ELSEWHERE_MM, depth_over(1.7, muscle))
    palpate_at(good, [0.0, 0.0, 50.0], depth_over(1.7, muscle))
    good.done()
    good.write(os.path.join(RES, "exercises", "no_lump.good.path"))

    bad = Script("no_lump.json done badly: swept, then two lumps reported where there are none")
    sweep_rows(bad, search, SEARCH_MM_PER_S)
    palpate_at(bad, ELSEWHERE_MM, depth_over(1.7, muscle), mark=True)
    palpate_at(bad, [0.0, 0.0, 50.0], depth_over(1.7, muscle), mark=True)
    bad.done()
    bad.write(os.path.join(RES, "exercises", "no_lump.bad.path"))


if __name__ == "__main__":
    press_targets()
    find_lump()
    trace()
    detect_lumps()
    no_lump()
