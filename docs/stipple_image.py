"""stipple_image.py - draw docs/stipple.pgm, the picture of the stippling example.

    python3 docs/stipple_image.py > docs/stipple.pgm

A 128 x 128 grey-scale face made of smooth shapes and gradients (a shaded
oval, hair, eyes, brows, nose, mouth, shoulders, a graded background),
written as a binary PGM (P5, maxval 255): 0 is black, 255 white. Standard
library only and no randomness, so the same bytes come out every time. The
poissondisk program turns it into a radius map (--radius-map, black dense,
white sparse); `make stipple-picture` draws docs/stipple.svg from it.
"""
import math
import sys

SIZE = 128


def smooth(edge0, edge1, x):
    """0 below edge0, 1 above edge1, a smooth step between."""
    t = min(1.0, max(0.0, (x - edge0) / (edge1 - edge0)))
    return t * t * (3 - 2 * t)


def ellipse(u, v, cu, cv, ru, rv, soft=0.08):
    """1 inside the ellipse, 0 outside, blurred over a band of relative width soft."""
    d = math.hypot((u - cu) / ru, (v - cv) / rv)
    return 1.0 - smooth(1.0 - soft, 1.0 + soft, d)


def stroke(u, v, cu, cv, ru, rv, a0, a1, width):
    """A soft arc of the ellipse (cu, cv, ru, rv) between the angles a0 and a1 (radians)."""
    a = math.atan2((v - cv) / rv, (u - cu) / ru)
    if not a0 <= a <= a1:
        return 0.0
    d = abs(math.hypot((u - cu) / ru, (v - cv) / rv) - 1.0) * min(ru, rv)
    return 1.0 - smooth(0.4 * width, width, d)


def mix(a, b, t):
    return a + (b - a) * t


def grey(u, v):
    """The grey level, 0 (black) to 1 (white), at (u, v): u to the right, v downwards."""
    # The background: light at the top, darker below, a little vignetting.
    g = mix(1.0, 0.8, v) - 0.25 * (math.hypot(u - 0.5, v - 0.45) ** 2)
    # Shoulders.
    g = mix(g, mix(0.35, 0.1, v), ellipse(u, v, 0.5, 1.08, 0.46, 0.24, 0.06))
    # Neck.
    g = mix(g, 0.62, ellipse(u, v, 0.5, 0.86, 0.11, 0.14, 0.15))
    # Hair behind the face.
    hair = ellipse(u, v, 0.5, 0.44, 0.35, 0.38, 0.05)
    g = mix(g, 0.15, hair)
    # The face: a sphere lit from the upper left.
    face = ellipse(u, v, 0.5, 0.55, 0.27, 0.34, 0.06)
    x, y = (u - 0.5) / 0.27, (v - 0.55) / 0.34
    z = math.sqrt(max(0.0, 1.0 - x * x - y * y))
    light = max(0.0, (-0.45 * x - 0.35 * y + 0.82 * z))
    g = mix(g, 0.2 + 0.8 * light, face)
    # The fringe: hair over the forehead.
    fringe = ellipse(u, v, 0.5, 0.19, 0.33, 0.17, 0.12) * hair
    g = mix(g, 0.15, fringe)
    # Eyes: white, a dark iris, brows above.
    for cu in (0.39, 0.61):
        g = mix(g, 1.0, ellipse(u, v, cu, 0.50, 0.07, 0.036, 0.2))
        g = mix(g, 0.0, ellipse(u, v, cu + 0.008, 0.50, 0.03, 0.03, 0.25))
        g = mix(g, 0.0, stroke(u, v, cu, 0.465, 0.08, 0.05, -2.9, -0.25, 0.02))
    # The nose: a shadow on its right side and below it.
    g = mix(g, 0.2, stroke(u, v, 0.47, 0.60, 0.05, 0.09, -1.2, 0.9, 0.018))
    g = mix(g, 0.3, ellipse(u, v, 0.51, 0.67, 0.045, 0.015, 0.5))
    # The mouth: a smile.
    g = mix(g, 0.0, stroke(u, v, 0.5, 0.70, 0.12, 0.065, 0.35, 2.8, 0.022))
    return min(1.0, max(0.0, g))


def main():
    out = sys.stdout.buffer
    out.write(b"P5\n# poissondisk stippling example (docs/stipple_image.py)\n")
    out.write(b"%d %d\n255\n" % (SIZE, SIZE))
    row = bytearray(SIZE)
    for j in range(SIZE):
        for i in range(SIZE):
            # Pixel centres; 2 x 2 samples per pixel smooth the edges a little more.
            s = 0.0
            for a in (0.25, 0.75):
                for b in (0.25, 0.75):
                    s += grey((i + a) / SIZE, (j + b) / SIZE)
            row[i] = int(round(255 * s / 4))
        out.write(bytes(row))


if __name__ == "__main__":
    main()
