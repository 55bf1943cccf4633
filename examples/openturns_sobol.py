"""An OpenTURNS Sobol' study driving slipfield through its Python package,
beside `slipfield sensitivity` on the same scene and ranges.

    PYTHONPATH=python /usr/bin/python3 examples/openturns_sobol.py [ROWS]

OpenTURNS (python3-openturns) makes the pick-freeze design over the four
parameters (log10 l/R, the CV, v_b, the mean COF) and estimates the
indices (Saltelli's first order, Jansen's total, bootstrap intervals);
slipfield.evaluate runs the model at each row.  The field is a fifth
input in both: a white noise fixed on the belt (cof_generator =
belt_noise), keyed by the design's row, so A_B^(i) keeps A's field and B
has its own: the evaluation of block k, row j takes realisation j (A and
every A_B^(i)) or n + j (B), as `slipfield sensitivity` keys its runs.
The two studies draw different designs, so they agree within their
intervals, not to the bit.  Ranges narrow enough to run in under a
minute: log10 l/R in [0, 1], T = 60 s.
"""
import os
import subprocess
import sys
import tempfile

import openturns as ot
import pandas as pd

import slipfield

ROWS = int(sys.argv[1]) if len(sys.argv) > 1 else 64
TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SCENE = "cof = field\ncof_generator = belt_noise\nT = 60\nt_skip = 10\nseed = 20261201\n"
RANGES = {"log10_l_over_R": (0.0, 1.0), "cv": (0.1, 0.3), "v_b": (0.1, 0.6), "mu_mean": (0.2, 1.0)}
QOI = "pv_x_ratio"


def design_table(X, n):
    """OpenTURNS's rows as slipfield's scene keys and realisations."""
    rows = []
    for e in range(X.getSize()):
        k, j = divmod(e, n)
        u, cv, vb, mu = (X[e, i] for i in range(4))
        rows.append({"l_over_R": 10 ** u, "v_b": vb, "mu_mean": mu, "mu_std": cv * mu,
                     "realisation": n + j if k == 1 else j})
    return pd.DataFrame(rows)


def openturns_study(n):
    ot.RandomGenerator.SetSeed(20261201)
    dist = ot.ComposedDistribution([ot.Uniform(*RANGES[k]) for k in RANGES])
    X = ot.SobolIndicesExperiment(dist, n, False).generate()
    out = slipfield.evaluate(SCENE, design_table(X, n), unum=False)
    if (out["status"] != "ok").any():
        raise SystemExit("a run failed: %s" % out.loc[out["status"] != "ok", "status"].iloc[0])
    Y = ot.Sample([[v] for v in out[QOI]])
    res = {}
    for name, alg in (("S1", ot.SaltelliSensitivityAlgorithm(X, Y, n)), ("ST", ot.JansenSensitivityAlgorithm(X, Y, n))):
        alg.setBootstrapSize(500)
        alg.setConfidenceLevel(0.95)
        val = alg.getFirstOrderIndices() if name == "S1" else alg.getTotalOrderIndices()
        iv = alg.getFirstOrderIndicesInterval() if name == "S1" else alg.getTotalOrderIndicesInterval()
        res[name] = [(val[i], iv.getLowerBound()[i], iv.getUpperBound()[i]) for i in range(4)]
    return res


def slipfield_study(n):
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "s.scene")
        with open(sc, "w") as f:
            f.write(SCENE)
        out = os.path.join(d, "idx.tsv")
        r = RANGES
        subprocess.run([os.path.join(TOP, "build", "slipfield"), "sensitivity", sc, "--rows", str(n), "--out", out,
                        "--log-lr", "%g,%g" % r["log10_l_over_R"], "--cv", "%g,%g" % r["cv"],
                        "--vb", "%g,%g" % r["v_b"], "--mu", "%g,%g" % r["mu_mean"]],
                       check=True, capture_output=True)
        t = pd.read_csv(out, sep="\t")
    t = t[t["qoi"] == QOI].set_index("input")
    return {"S1": [(t.loc[k, "S1"], t.loc[k, "S1_ci95_lo"], t.loc[k, "S1_ci95_hi"]) for k in RANGES],
            "ST": [(t.loc[k, "ST"], t.loc[k, "ST_ci95_lo"], t.loc[k, "ST_ci95_hi"]) for k in RANGES]}


def main():
    a, b = openturns_study(ROWS), slipfield_study(ROWS)
    agree = True
    print("%s, %d rows each: index, OpenTURNS [95%%], slipfield sensitivity [95%%], intervals overlap" % (QOI, ROWS))
    for name in ("S1", "ST"):
        for i, k in enumerate(RANGES):
            (x, xl, xh), (y, yl, yh) = a[name][i], b[name][i]
            ok = xl <= yh and yl <= xh
            agree &= ok
            print("%s(%s)\t%.3f [%.3f, %.3f]\t%.3f [%.3f, %.3f]\t%s" % (name, k, x, xl, xh, y, yl, yh,
                                                                         "yes" if ok else "NO"))
    print("agree within their intervals: %s" % ("yes" if agree else "NO"))
    return 0 if agree else 1


if __name__ == "__main__":
    sys.exit(main())
