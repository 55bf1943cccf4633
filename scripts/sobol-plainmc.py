#!/usr/bin/python3
"""First-order Sobol' indices of the QoI ratios from plain Monte Carlo,
computed without slipfield's estimators: an independent check of the
study's (cases/validation/paper-claims-sobol; its record is
docs/studies/2026-12-02-sobol-plain-mc-check.md).

    scripts/sobol-plainmc.py run ROWS SEED OFFSET OUT.tsv   # design + slipfield evaluate
    scripts/sobol-plainmc.py analyse OUT.tsv [OUT2.tsv ...]  # the indices

`run` draws ROWS parameter sets uniform over the study's ranges (log10
l/R in [-2, 3], the CV in [0.1, 0.3], v_b in [0.1, 0.6] m/s, the mean
COF in [0.2, 1]) with numpy's generator at SEED, each with its own field
(realisation OFFSET + j of the belt noise, cof_generator = belt_noise;
T = 100 s, t_skip = 10 s, Table 1 otherwise), and runs them with
`slipfield evaluate` (no u_num).  `analyse` estimates S1 = Var(E[Y|x_i])
/ Var(Y) for each parameter by the binned conditional variance: 16 bins
of equal count along x_i, the variance of the bin means less the mean
within-bin variance over the bin size (its small-bin bias), with a 95%
normal interval from the standard deviation of 400 bootstrap resamples
of the rows (and the same for S1(l/R) less the largest other S1); beside it,
the rank estimator (neighbours in x_i's order) as a second reading.
numpy and pandas from Debian (/usr/bin/python3).
"""
import os
import subprocess
import sys

import numpy as np
import pandas as pd

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
R = 0.5
SCENE = ("m = 10\nk = 30\nR = 0.5\nmu_k_ratio = 0.9\ncof = field\ncof_generator = belt_noise\n"
         "T = 100\nt_skip = 10\nseed = 20230101\n")
NAMES = ["log10 l/R", "CV", "v_b", "mean COF"]
QOIS = ["pv_x_ratio[-]", "pv_F_ratio[-]", "stick_fraction_ratio[-]"]


def run(rows, seed, offset, out):
    u = np.random.default_rng(seed).random((rows, 4))
    lg, cv, vb, mu = -2 + 5 * u[:, 0], 0.1 + 0.2 * u[:, 1], 0.1 + 0.5 * u[:, 2], 0.2 + 0.8 * u[:, 3]
    design = out + ".design"
    with open(design, "w") as f:
        f.write("l\tv_b\tmu_mean\tmu_std\trealisation\n")
        for j in range(rows):
            f.write(f"{10 ** lg[j] * R!r}\t{vb[j]!r}\t{mu[j]!r}\t{cv[j] * mu[j]!r}\t{offset + j}\n")
    scene = out + ".scene"
    with open(scene, "w") as f:
        f.write(SCENE)
    subprocess.run([os.path.join(TOP, "build", "slipfield"), "evaluate", scene, "--design", design, "--out", out,
                    "--no-unum"], check=True)


def binned(x, y, k=16):
    bins = np.array_split(y[np.argsort(x)], k)
    n = np.array([len(b) for b in bins])
    m = np.array([b.mean() for b in bins])
    w = np.array([b.var(ddof=1) for b in bins])
    return (np.sum(n * (m - y.mean()) ** 2) - np.sum(w)) / len(y) / y.var(ddof=1)


def rank(x, y):
    yc = y[np.argsort(x)] - y.mean()
    return (np.sum(yc[:-1] * yc[1:]) + yc[-1] * yc[0]) / len(y) / np.mean(yc ** 2)


def analyse(files):
    d = pd.concat([pd.read_csv(f, sep="\t") for f in files])
    d = d[d.status == "ok"]
    X = np.column_stack([np.log10(d["l"] / R), d["mu_std"] / d["mu_mean"], d["v_b"], d["mu_mean"]])
    rng = np.random.default_rng(1)
    for q in QOIS:
        y = d[q].to_numpy()
        ok = np.isfinite(y)
        y, Xq = y[ok], X[ok]
        print(f"{q}: {len(y)} rows, mean {y.mean():.4f}, sd {y.std(ddof=1):.4f}")
        est = np.array([binned(Xq[:, i], y) for i in range(4)])
        boot = []
        for _ in range(400):
            s = rng.integers(0, len(y), len(y))
            boot.append([binned(Xq[s, i], y[s]) for i in range(4)])
        sd = np.std(boot, axis=0, ddof=1)   # normal intervals: the resampled bins' bias shifts the percentiles
        for i, name in enumerate(NAMES):
            print(f"  {name:10s} S1 binned {est[i]:6.3f} [{est[i] - 1.96 * sd[i]:6.3f}, {est[i] + 1.96 * sd[i]:6.3f}]"
                  f"   rank {rank(Xq[:, i], y):6.3f}")
        gap = est[0] - est[1:].max()
        gsd = np.std([b[0] - max(b[1:]) for b in boot], ddof=1)
        print(f"  S1(l/R) - the largest other: {gap:6.3f} [{gap - 1.96 * gsd:6.3f}, {gap + 1.96 * gsd:6.3f}]")


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "run":
        run(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5])
    elif len(sys.argv) >= 3 and sys.argv[1] == "analyse":
        analyse(sys.argv[2:])
    else:
        sys.exit(__doc__)
