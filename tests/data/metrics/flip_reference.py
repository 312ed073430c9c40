#!/usr/bin/env python3
"""Independent LDR-FLIP reference for tests/test_metrics.cpp.

Pure Python, double precision, with the paper's *non-separable* 2D filters (as in FLIP's original
Python code), whereas harness/metrics/flip.cpp uses separable single-precision passes. The images are
built from the formula in pattern_images() (duplicated in the C++ test); all values are dyadic
rationals so both sides see exactly the same inputs.

Usage: python3 flip_reference.py > flip_reference.json
"""
import json
import math

PPD = 67.0
WIDTH, HEIGHT = 24, 20


def pattern_images():
    """Returns (reference, test) as lists of rows of (r, g, b) linear RGB tuples."""
    reference, test = [], []
    for y in range(HEIGHT):
        ref_row, test_row = [], []
        for x in range(WIDTH):
            r = ((3 * x + y) % 16) / 16.0
            g = 0.75 if x >= 12 else 0.125
            b = ((x * y) % 8) / 8.0
            ref_row.append((r, g, b))
            tr = ((3 * x + y + 1) % 16) / 16.0 if y < 10 else r
            tg = 0.75 if x >= 13 else 0.125          # edge shifted by one pixel
            tb = b * 0.5 if x < 6 else b
            test_row.append((tr, tg, tb))
        reference.append(ref_row)
        test.append(test_row)
    return reference, test


WHITE = (0.950428545, 1.0, 1.088900371)


def rgb_to_xyz(c):
    r, g, b = c
    return (10135552 / 24577794 * r + 8788810 / 24577794 * g + 4435075 / 24577794 * b,
            2613072 / 12288897 * r + 8788810 / 12288897 * g + 887015 / 12288897 * b,
            1425312 / 73733382 * r + 8788810 / 73733382 * g + 70074185 / 73733382 * b)


def xyz_to_rgb(c):
    x, y, z = c
    return (3.241003275 * x - 1.537398934 * y - 0.498615861 * z,
            -0.969224334 * x + 1.875930071 * y + 0.041554224 * z,
            0.055639423 * x - 0.204011202 * y + 1.057148933 * z)


def xyz_to_ycxcz(c):
    x, y, z = (c[i] / WHITE[i] for i in range(3))
    return (116 * y - 16, 500 * (x - y), 200 * (y - z))


def ycxcz_to_xyz(c):
    y = (c[0] + 16) / 116
    return ((y + c[1] / 500) * WHITE[0], y * WHITE[1], (y - c[2] / 200) * WHITE[2])


def xyz_to_lab(c):
    d = 6 / 29

    def f(t):
        return t ** (1 / 3) if t > d ** 3 else t / (3 * d * d) + 4 / 29
    fx, fy, fz = (f(c[i] / WHITE[i]) for i in range(3))
    return (116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz))


def hunt(lab):
    return (lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2])


def hyab(a, b):
    return abs(a[0] - b[0]) + math.hypot(a[1] - b[1], a[2] - b[2])


def clamp01(c):
    return tuple(min(max(v, 0.0), 1.0) for v in c)


def convolve2d(plane, kernel):
    """Clamp-to-edge 2D convolution; kernel is a square list of rows (symmetric use, no flip needed)."""
    r = len(kernel) // 2
    out = [[0.0] * WIDTH for _ in range(HEIGHT)]
    for y in range(HEIGHT):
        for x in range(WIDTH):
            s = 0.0
            for ky in range(-r, r + 1):
                yy = min(max(y + ky, 0), HEIGHT - 1)
                row = kernel[ky + r]
                src = plane[yy]
                for kx in range(-r, r + 1):
                    s += row[kx + r] * src[min(max(x + kx, 0), WIDTH - 1)]
            out[y][x] = s
    return out


def spatial_kernel(gaussians):
    radius = math.ceil(3 * math.sqrt(0.04 / (2 * math.pi ** 2)) * PPD)
    k = [[0.0] * (2 * radius + 1) for _ in range(2 * radius + 1)]
    for j in range(-radius, radius + 1):
        for i in range(-radius, radius + 1):
            d2 = (i / PPD) ** 2 + (j / PPD) ** 2
            k[j + radius][i + radius] = sum(a * math.sqrt(math.pi / b) * math.exp(-math.pi ** 2 * d2 / b)
                                            for a, b in gaussians)
    total = sum(map(sum, k))
    return [[v / total for v in row] for row in k]


def feature_kernels(second_derivative):
    sd = 0.5 * 0.082 * PPD
    radius = math.ceil(3 * sd)
    gx = [[0.0] * (2 * radius + 1) for _ in range(2 * radius + 1)]
    for j in range(-radius, radius + 1):
        for i in range(-radius, radius + 1):
            g = math.exp(-(i * i + j * j) / (2 * sd * sd))
            gx[j + radius][i + radius] = (i * i / (sd * sd) - 1) * g if second_derivative else -i * g
    pos = sum(v for row in gx for v in row if v > 0)
    neg = -sum(v for row in gx for v in row if v < 0)
    gx = [[v / pos if v > 0 else v / neg for v in row] for row in gx]
    gy = [list(col) for col in zip(*gx)]
    return gx, gy


def flip_map(reference, test):
    opp = {}
    for name, img in (("ref", reference), ("test", test)):
        conv = [[xyz_to_ycxcz(rgb_to_xyz(clamp01(p))) for p in row] for row in img]
        opp[name] = [[[conv[y][x][c] for x in range(WIDTH)] for y in range(HEIGHT)] for c in range(3)]

    kernels = [spatial_kernel([(1.0, 0.0047)]), spatial_kernel([(1.0, 0.0053)]),
               spatial_kernel([(34.1, 0.04), (13.5, 0.025)])]
    filtered = {n: [convolve2d(opp[n][c], kernels[c]) for c in range(3)] for n in opp}

    def lab_at(n, x, y):
        c = tuple(filtered[n][i][y][x] for i in range(3))
        return hunt(xyz_to_lab(rgb_to_xyz(clamp01(xyz_to_rgb(ycxcz_to_xyz(c))))))

    green = hunt(xyz_to_lab(rgb_to_xyz((0, 1, 0))))
    blue = hunt(xyz_to_lab(rgb_to_xyz((0, 0, 1))))
    cmax = hyab(green, blue) ** 0.7
    pccmax = 0.4 * cmax

    feats = {}
    edge_x, edge_y = feature_kernels(False)
    point_x, point_y = feature_kernels(True)
    for n in opp:
        gray = [[(v + 16) / 116 for v in row] for row in opp[n][0]]
        ex, ey = convolve2d(gray, edge_x), convolve2d(gray, edge_y)
        px, py = convolve2d(gray, point_x), convolve2d(gray, point_y)
        feats[n] = ([[math.hypot(ex[y][x], ey[y][x]) for x in range(WIDTH)] for y in range(HEIGHT)],
                    [[math.hypot(px[y][x], py[y][x]) for x in range(WIDTH)] for y in range(HEIGHT)])

    out = []
    for y in range(HEIGHT):
        for x in range(WIDTH):
            dc = hyab(lab_at("ref", x, y), lab_at("test", x, y)) ** 0.7
            dc = dc * 0.95 / pccmax if dc < pccmax else 0.95 + (dc - pccmax) / (cmax - pccmax) * 0.05
            de = abs(feats["ref"][0][y][x] - feats["test"][0][y][x])
            dp = abs(feats["ref"][1][y][x] - feats["test"][1][y][x])
            df = (max(de, dp) / math.sqrt(2)) ** 0.5
            out.append(dc ** (1 - df))
    return out


def weighted_median(values):
    values = sorted(values)
    total, running = sum(values), 0.0
    for v in values:
        running += v
        if running > 0.5 * total:
            return v
    return 0.0


if __name__ == "__main__":
    ref, tst = pattern_images()
    fmap = flip_map(ref, tst)
    print(json.dumps({
        "description": "LDR-FLIP of pattern_images() (see flip_reference.py), non-separable double-precision reference",
        "pixels_per_degree": PPD, "width": WIDTH, "height": HEIGHT,
        "mean": sum(fmap) / len(fmap), "weighted_median": weighted_median(fmap),
        "map": [round(v, 7) for v in fmap],
    }, indent=1))
