#!/usr/bin/env python3
"""A cosine-weighted hemisphere sampler that speaks mcbox-check's --exec protocol
(docs/check-protocol.md), with the standard library only:

    mcbox-check --exec 'python3 docs/protocol/cosine.py' --domain hemisphere --invert
"""
import math
import sys


# BEGIN SNIPPET own_py_warp
def sample(u1, u2):  # Malley: a uniform point of the disc, lifted to the hemisphere
    r, phi = math.sqrt(u1), 2.0 * math.pi * u2
    return r * math.cos(phi), r * math.sin(phi), math.sqrt(max(0.0, 1.0 - u1))


def pdf(x, y, z):  # per unit solid angle
    return z / math.pi if z >= 0.0 else 0.0


def invert(x, y, z):
    return x * x + y * y, (math.atan2(y, x) / (2.0 * math.pi)) % 1.0
# END SNIPPET own_py_warp


# BEGIN SNIPPET own_py_protocol
def main():
    out = sys.stdout
    for line in sys.stdin:
        cmd = line.split()
        if cmd and cmd[0] == "hello":
            out.write("ok\n")
        elif cmd and cmd[0] in ("sample", "pdf", "invert"):
            items = [[float(v) for v in sys.stdin.readline().replace(",", " ").split()]
                     for _ in range(int(cmd[1]))]
            if cmd[0] == "sample":  # the point, then the optional pdf column
                pts = [sample(*v) for v in items]
                text = ["%r %r %r %r\n" % (x, y, z, pdf(x, y, z)) for x, y, z in pts]
            elif cmd[0] == "pdf":
                text = ["%r\n" % pdf(*v) for v in items]
            else:
                text = ["%r %r\n" % invert(*v) for v in items]
            out.write("".join(text))
        else:
            out.write("error unknown command %r\n" % line.strip())
            out.flush()
            return 2
        out.flush()  # mcbox-check waits for the whole batch: never leave it in a buffer
    return 0
# END SNIPPET own_py_protocol


if __name__ == "__main__":
    sys.exit(main())
