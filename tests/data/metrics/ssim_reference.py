#!/usr/bin/env python3
"""Independent SSIM reference for tests/test_metrics.cpp.

Direct (non-separable) 11x11 Gaussian window, sigma 1.5, valid region, K1 = 0.01, K2 = 0.03, L = 1,
on clamped Rec. 709 luminance of the images from flip_reference.pattern_images().

Usage: python3 ssim_reference.py > ssim_reference.json
"""
import json
import math

from flip_reference import HEIGHT, WIDTH, pattern_images


def luminance(image):
    return [[min(max(0.2126 * r + 0.7152 * g + 0.0722 * b, 0.0), 1.0) for (r, g, b) in row] for row in image]


def mean_ssim(a, b):
    radius, sigma = 5, 1.5
    window = [[math.exp(-(i * i + j * j) / (2 * sigma * sigma)) for i in range(-radius, radius + 1)]
              for j in range(-radius, radius + 1)]
    total = sum(map(sum, window))
    window = [[w / total for w in row] for row in window]
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    values = []
    for y in range(radius, HEIGHT - radius):
        for x in range(radius, WIDTH - radius):
            ma = mb = maa = mbb = mab = 0.0
            for j in range(-radius, radius + 1):
                for i in range(-radius, radius + 1):
                    w = window[j + radius][i + radius]
                    va, vb = a[y + j][x + i], b[y + j][x + i]
                    ma += w * va
                    mb += w * vb
                    maa += w * va * va
                    mbb += w * vb * vb
                    mab += w * va * vb
            va, vb, cov = maa - ma * ma, mbb - mb * mb, mab - ma * mb
            values.append((2 * ma * mb + c1) * (2 * cov + c2) / ((ma * ma + mb * mb + c1) * (va + vb + c2)))
    return sum(values) / len(values)


if __name__ == "__main__":
    reference, test = pattern_images()
    print(json.dumps({
        "description": "mean SSIM of pattern_images() in flip_reference.py (test vs reference)",
        "width": WIDTH, "height": HEIGHT,
        "ssim": mean_ssim(luminance(test), luminance(reference)),
    }, indent=1))
