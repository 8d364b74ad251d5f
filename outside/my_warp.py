#!/usr/bin/env python3
"""my_warp.py - the cosine-weighted hemisphere of my_warp.c (Malley's method on
Shirley and Chiu's concentric disc) in Python, standard library only, speaking
mcbox-check's --exec protocol on stdin/stdout:

    mcbox-check --exec 'python3 my_warp.py' --domain hemisphere --invert

With --wrong-pdf it forgets the density's 1/pi: mcbox-check must reject that.
"""
import math, sys

WRONG = "--wrong-pdf" in sys.argv[1:]

def sample(u1, u2):  # the concentric disc point, lifted to the hemisphere
    sx, sy = 2.0 * u1 - 1.0, 2.0 * u2 - 1.0
    if sx == 0.0 and sy == 0.0:
        return 0.0, 0.0, 1.0
    if abs(sx) > abs(sy):
        r, phi = sx, math.pi / 4.0 * (sy / sx)
    else:
        r, phi = sy, math.pi / 2.0 - math.pi / 4.0 * (sx / sy)
    x, y = r * math.cos(phi), r * math.sin(phi)
    return x, y, math.sqrt(max(0.0, 1.0 - x * x - y * y))

def pdf(x, y, z):  # cos(theta) / pi per unit solid angle
    return (z if WRONG else z / math.pi) if z >= 0.0 else 0.0

def invert(x, y, z):  # back to the disc, then undo the concentric map wedge by wedge
    r, psi = math.hypot(x, y), math.atan2(y, x)
    if abs(psi) <= math.pi / 4.0 or abs(psi) >= 3.0 * math.pi / 4.0:
        phi = psi if x >= 0.0 else (psi - math.pi if psi > 0.0 else psi + math.pi)
        sx = r if x >= 0.0 else -r
        sy = sx * phi * 4.0 / math.pi
    else:
        sy = r if y >= 0.0 else -r
        sx = sy * (math.pi / 2.0 - (psi if y >= 0.0 else psi + math.pi)) * 4.0 / math.pi
    return 0.5 * (sx + 1.0), 0.5 * (sy + 1.0)

def with_pdf(p):  # the point, then the optional pdf column
    return p + (pdf(*p),)

ANSWER = {"sample": lambda v: "%r %r %r %r" % with_pdf(sample(*v)),
          "pdf": lambda v: "%r" % pdf(*v), "invert": lambda v: "%r %r" % invert(*v)}
for line in sys.stdin:
    cmd = line.split()
    if cmd[0] == "hello":
        print("ok")
    elif cmd[0] in ANSWER:
        items = [[float(t) for t in sys.stdin.readline().replace(",", " ").split()]
                 for _ in range(int(cmd[1]))]
        sys.stdout.write("".join(ANSWER[cmd[0]](v) + "\n" for v in items))
    else:
        print("error unknown command " + cmd[0])
        sys.exit(1)
    sys.stdout.flush()
