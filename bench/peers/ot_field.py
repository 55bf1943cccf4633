"""Peer for `make bench` (field section): OpenTURNS GaussianProcess with its
Cholesky sampling method, squared-exponential field exp(-r^2/l^2) on an
n x n grid of spacing dx (OpenTURNS SquaredExponential theta = l/sqrt(2)).

Usage: /usr/bin/python3 ot_field.py n dx l reps
Prints one line:
  peer=openturns method=cholesky n=N setup_s=S sample_s=T cov_err=E reps=R version=V
Timing is inside Python (interpreter and import excluded).  The first
getRealization() builds and factors the covariance (set-up + one field);
set-up = first - median(later calls).  cov_err = max |L L^T - Sigma| of
OpenTURNS' own Cholesky factor of its discretised covariance (computed
after the timing, with numpy).
"""
import math
import statistics
import sys
import time

if len(sys.argv) != 5:
    sys.stderr.write("usage: ot_field.py n dx l reps\n")
    sys.exit(2)
n, dx, l, reps = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])

import numpy as np  # noqa: E402
import openturns as ot  # noqa: E402

ot.Log.Show(ot.Log.NONE)
mesh = ot.IntervalMesher([n - 1, n - 1]).build(ot.Interval([0.0, 0.0], [(n - 1) * dx] * 2))
theta = l / math.sqrt(2.0)
model = ot.SquaredExponential([theta, theta], [1.0])

t0 = time.perf_counter()
proc = ot.GaussianProcess(model, mesh)
proc.setSamplingMethod(ot.GaussianProcess.CHOLESKY)
first = proc.getRealization()
t1 = time.perf_counter()
times = []
for _ in range(reps):
    s = time.perf_counter()
    proc.getRealization()
    times.append(time.perf_counter() - s)
per = statistics.median(times)
assert first.getValues().getSize() == n * n

cov = model.discretize(mesh)
L = np.array(cov.computeCholesky())
S = np.array(cov)
err = float(np.abs(L @ L.T - S).max())
print("peer=openturns method=cholesky n=%d setup_s=%.6g sample_s=%.6g cov_err=%.3g reps=%d version=%s"
      % (n, (t1 - t0) - per, per, err, reps, ot.__version__))
