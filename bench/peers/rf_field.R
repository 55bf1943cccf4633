# Peer for `make bench` (field section): R RandomFields circulant embedding
# of the squared-exponential field exp(-r^2/l^2) = RMgauss(scale = l) on an
# n x n grid of spacing dx.  Usage: Rscript rf_field.R n dx l reps
# Prints one line:
#   peer=randomfields method=circulant n=N setup_s=S sample_s=T reps=R tol_re=X version=V
# (tol_re: RandomFields clamps embedding eigenvalues above this to zero.)
# Timing is inside R (interpreter and package start-up excluded): one call
# with n = 1 costs set-up + 1 field, one with n = 1 + reps costs set-up +
# (1 + reps) fields (one initialisation per call, storing = FALSE), so
# per field = difference / reps and set-up = first - per field.
args <- commandArgs(trailingOnly = TRUE)
if (length(args) != 4) {
  cat("usage: Rscript rf_field.R n dx l reps\n", file = stderr()); quit(status = 2)
}
n <- as.integer(args[1]); dx <- as.numeric(args[2]); l <- as.numeric(args[3])
reps <- as.integer(args[4])
suppressPackageStartupMessages(library(RandomFields))
RFoptions(spConform = FALSE, printlevel = 0, cPrintlevel = 0, storing = FALSE,
          install = "no", seed = NA)
x <- seq(0, by = dx, length.out = n)
model <- RPcirculant(RMgauss(scale = l))
elapsed <- function(k) {
  t0 <- proc.time()[["elapsed"]]
  z <- RFsimulate(model, x = x, y = x, grid = TRUE, n = k)
  t1 <- proc.time()[["elapsed"]]
  stopifnot(length(z) == n * n * k)
  t1 - t0
}
invisible(elapsed(1))   # warm-up (first-call dispatch)
t1 <- elapsed(1)
tk <- elapsed(1 + reps)
per <- (tk - t1) / reps
cat(sprintf("peer=randomfields method=circulant n=%d setup_s=%.6g sample_s=%.6g reps=%d tol_re=%g version=%s\n",
            n, t1 - per, per, reps, RFoptions()$circulant$tolRe,
            as.character(packageVersion("RandomFields"))))
