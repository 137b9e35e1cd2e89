#!/usr/bin/env python3
"""Writes a graphdeco 3DGS PLY of COUNT Gaussians (SH degree 3), a capture-like scene: a ball
of small opaque Gaussians inside a torus of larger, softer ones, seeded, for timings that need a
Gaussian file of a given size (docs/tools/quilt_pipeline.sh).
Usage: gaussians_ply.py COUNT OUT.ply   (needs numpy)"""
import sys

import numpy as np

count, path = int(sys.argv[1]), sys.argv[2]
rng = np.random.default_rng(7)
ball = count // 2
torus = count - ball
d = rng.normal(size=(ball, 3))
ball_xyz = d / np.linalg.norm(d, axis=1, keepdims=True) * (0.5 * rng.random((ball, 1)) ** (1 / 3))
a, b = rng.random(torus) * 2 * np.pi, rng.random(torus) * 2 * np.pi
r = 0.25 * np.sqrt(rng.random(torus))
torus_xyz = np.stack([(1.0 + r * np.cos(b)) * np.cos(a), r * np.sin(b), (1.0 + r * np.cos(b)) * np.sin(a)], 1)
xyz = np.concatenate([ball_xyz, torus_xyz]).astype(np.float32)
fields = ["x", "y", "z", "nx", "ny", "nz"] + [f"f_dc_{i}" for i in range(3)] + \
    [f"f_rest_{i}" for i in range(45)] + ["opacity"] + [f"scale_{i}" for i in range(3)] + \
    [f"rot_{i}" for i in range(4)]
data = np.zeros((count, len(fields)), np.float32)
data[:, 0:3] = xyz
hue = np.concatenate([rng.random(ball) * 0.3, 0.5 + rng.random(torus) * 0.3])
data[:, 6] = 1.5 * np.cos(2 * np.pi * hue)
data[:, 7] = 1.5 * np.cos(2 * np.pi * (hue - 1 / 3))
data[:, 8] = 1.5 * np.cos(2 * np.pi * (hue + 1 / 3))
data[:, 9:54] = rng.normal(scale=0.05, size=(count, 45))
data[:, 54] = np.concatenate([np.full(ball, 3.0), np.full(torus, 0.5)])  # logit opacity
scale = np.concatenate([np.full(ball, np.log(0.012)), np.full(torus, np.log(0.03))])
data[:, 55:58] = (scale[:, None] + rng.normal(scale=0.3, size=(count, 3))).astype(np.float32)
q = rng.normal(size=(count, 4))
data[:, 58:62] = q / np.linalg.norm(q, axis=1, keepdims=True)
header = "ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % count + \
    "".join(f"property float {f}\n" for f in fields) + "end_header\n"
with open(path, "wb") as f:
    f.write(header.encode())
    f.write(data.tobytes())
