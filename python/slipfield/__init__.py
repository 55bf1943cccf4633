"""slipfield from Python: the stick-slip oscillator with a random-field
friction coefficient, through the C library's high-level calls
(solver/model.h) with ctypes.

    import slipfield
    slipfield.run("examples/disc.scene")                  # one realisation: dict
    slipfield.sweep("examples/disc.scene", "l_over_R", [0.5, 2], realisations=8)
    slipfield.evaluate("examples/disc.scene", design_df)   # an external design
    slipfield.results("reports/results.json")             # a verification run

Realisation i of a scene is the one `slipfield sweep` solves as its row i
(the COF drawn from the stream sf_mc_seed(seed, i)), `slipfield run
--realisation i` too.  Units: pv_x [m], pv_F [N], stick_fraction [-];
ratios to the deterministic model at the same parameters [-]; u_* the
numerical error of each QoI in its unit (ASME V&V 20, a coarser companion
solve of the same realisation).
"""

import ctypes
import ctypes.util
import math
import os

__all__ = ["run", "sweep", "evaluate", "results", "library", "SlipfieldError"]

QOIS = ("pv_x", "pv_F", "stick_fraction")
UNITS = {"pv_x": "m", "pv_F": "N", "stick_fraction": "-"}
ESTIMATORS = ("plain", "mlmc", "mlmc-boxes", "mlmc-sub", "antithetic", "auto")
_NOUT = 9      # SF_MODEL_NOUT: 3 QoIs, 3 ratios, 3 u_num
_NCOL = 6      # a sweep answer: estimate, se, ci_lo, ci_hi, u_num, n
_ERRLEN = 1024


class SlipfieldError(RuntimeError):
    """A call of the library failed: the library's reason, and its code."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


class _Spec(ctypes.Structure):   # sf_model_spec
    _fields_ = [("by", ctypes.c_int), ("n", ctypes.c_size_t), ("pilot", ctypes.c_size_t),
                ("target_se", ctypes.c_double), ("control_variate", ctypes.c_int), ("threads", ctypes.c_int),
                ("checkpoint", ctypes.c_char_p), ("resume", ctypes.c_int), ("label", ctypes.c_char_p)]


def _candidates():
    env = os.environ.get("SLIPFIELD_LIB")
    if env:
        yield env
    here = os.path.dirname(os.path.abspath(__file__))
    yield os.path.join(here, "..", "..", "build", "libslipfield.so")   # the source tree after `make`
    try:
        from . import _installed   # written by `make install`
        yield _installed.LIBRARY
    except ImportError:
        pass
    found = ctypes.util.find_library("slipfield")
    if found:
        yield found


_lib = None


def _pandas():
    """pandas, from Debian's python3-pandas when the interpreter running
    us is another one (a python3 first on PATH that does not see
    /usr/lib/python3/dist-packages)."""
    try:
        import pandas
        return pandas
    except ImportError:
        import sys
        deb = "/usr/lib/python3/dist-packages"
        if os.path.isdir(deb) and deb not in sys.path:
            sys.path.append(deb)
            try:
                import pandas
                return pandas
            except ImportError:
                sys.path.remove(deb)
        raise ImportError("slipfield needs pandas: apt-get install python3-pandas (Debian's /usr/bin/python3 "
                          "sees it)")


def library():
    """The loaded libslipfield (ctypes.CDLL): SLIPFIELD_LIB, the source
    tree's build/, the installed one, or the loader's search path."""
    global _lib
    if _lib is not None:
        return _lib
    tried = []
    for path in _candidates():
        tried.append(path)
        if os.path.sep in path and not os.path.exists(path):
            continue
        try:
            lib = ctypes.CDLL(path)
            break
        except OSError:
            continue
    else:
        raise SlipfieldError("libslipfield not found (tried %s): run `make` in the source tree, or set "
                             "SLIPFIELD_LIB" % ", ".join(tried), 0)
    P, C, S, D, I = ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t, ctypes.c_double, ctypes.c_int
    sig = {
        "sf_init": (I, []),
        "sf_version": (C, []),
        "sf_model_new": (I, [C, ctypes.POINTER(P), C, S]),
        "sf_model_load": (I, [C, ctypes.POINTER(P), C, S]),
        "sf_model_free": (None, [P]),
        "sf_model_set": (I, [P, C, C, C, S]),
        "sf_model_run": (I, [P, S, I, ctypes.POINTER(D), C, S]),
        "sf_model_estimator": (I, [C, ctypes.POINTER(I)]),
        "sf_model_sweep_run": (I, [P, C, ctypes.POINTER(D), S, ctypes.POINTER(_Spec), ctypes.POINTER(P), C, S]),
        "sf_model_sweep_points": (S, [P]),
        "sf_model_sweep_table": (I, [P, ctypes.POINTER(D), ctypes.POINTER(C)]),
        "sf_model_sweep_free": (None, [P]),
    }
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args
    lib.sf_init()
    _lib = lib
    return lib


def _check(rc, err):
    if rc:
        raise SlipfieldError(err.value.decode(errors="replace") or "error %d" % rc, rc)


class _Model:
    """An sf_model handle: the scene (a file's path, scene text, or None
    for the paper's Table 1 baseline) with keys set on it."""

    def __init__(self, scene=None, **keys):
        lib = library()
        self._lib, self._h = lib, ctypes.c_void_p()
        err = ctypes.create_string_buffer(_ERRLEN)
        if scene is not None and os.path.exists(str(scene)):
            rc = lib.sf_model_load(os.fsencode(str(scene)), ctypes.byref(self._h), err, _ERRLEN)
        else:
            rc = lib.sf_model_new(None if scene is None else str(scene).encode(), ctypes.byref(self._h), err,
                                  _ERRLEN)
        _check(rc, err)
        for k, v in keys.items():
            self.set(k, v)

    def set(self, key, value):
        err = ctypes.create_string_buffer(_ERRLEN)
        if isinstance(value, bool):
            value = "true" if value else "false"
        elif isinstance(value, float):
            value = repr(value)   # the shortest text that reads back to the same double
        _check(self._lib.sf_model_set(self._h, str(key).encode(), str(value).encode(), err, _ERRLEN), err)

    def run(self, realisation=0, unum=True):
        out = (ctypes.c_double * _NOUT)()
        err = ctypes.create_string_buffer(_ERRLEN)
        rc = self._lib.sf_model_run(self._h, int(realisation), 1 if unum else 0, out, err, _ERRLEN)
        _check(rc, err)
        d = {}
        for q, name in enumerate(QOIS):
            d[name] = out[q]
            d[name + "_ratio"] = out[3 + q]
            d["u_" + name] = out[6 + q]
        msg = err.value.decode(errors="replace")
        if msg:
            d["warning"] = msg
        return d

    def close(self):
        if self._h:
            self._lib.sf_model_free(self._h)
            self._h = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass


def run(scene=None, realisation=0, unum=True, **keys):
    """One realisation (the sweep's row `realisation`) of `scene` with
    `keys` set (any scene key, or l_over_R): a dict of the QoIs, their
    ratios to the deterministic model and their u_num (NaN without unum)."""
    with _Model(scene, **keys) as m:
        return m.run(realisation, unum)


def sweep(scene, param, values, realisations=None, target_se=None, estimator=None, pilot=None,
          control_variate=False, threads=0, **keys):
    """A sweep of `scene` over `param` (a scene key or l_over_R) at
    `values`: a tidy DataFrame, one row per value and QoI ratio, columns
    value, qoi, estimate, se, ci_lo, ci_hi, u_num, n, estimator, stop
    (as `slipfield sweep --summary-format long`).  realisations: N (the
    cap with target_se); estimator: plain (default), mlmc, mlmc-boxes,
    mlmc-sub, antithetic or auto."""
    pd = _pandas()
    lib = library()
    values = [float(v) for v in values]
    if realisations is None:
        raise SlipfieldError("sweep: realisations is required", 1)
    by = ctypes.c_int()
    if lib.sf_model_estimator(None if estimator is None else estimator.encode(), ctypes.byref(by)):
        raise SlipfieldError("sweep: estimator takes %s (got %r)" % (", ".join(ESTIMATORS), estimator), 1)
    spec = _Spec(by.value, int(realisations), int(pilot or 0), math.nan if target_se is None else float(target_se),
                 1 if control_variate else 0, int(threads), None, 0, None)
    vals = (ctypes.c_double * len(values))(*values)
    h, err = ctypes.c_void_p(), ctypes.create_string_buffer(_ERRLEN)
    with _Model(scene, **keys) as m:
        _check(lib.sf_model_sweep_run(m._h, str(param).encode(), vals, len(values), ctypes.byref(spec),
                                      ctypes.byref(h), err, _ERRLEN), err)
    try:
        k = len(values) * len(QOIS)
        f = (ctypes.c_double * (k * _NCOL))()
        names = (ctypes.c_char_p * (2 * k))()
        lib.sf_model_sweep_table(h, f, names)
    finally:
        lib.sf_model_sweep_free(h)
    rows = []
    for j in range(k):
        a = f[j * _NCOL:(j + 1) * _NCOL]
        rows.append({"value": values[j // 3], "qoi": QOIS[j % 3] + "_ratio", "estimate": a[0], "se": a[1],
                     "ci_lo": a[2], "ci_hi": a[3], "u_num": a[4], "n": int(a[5]),
                     "estimator": names[2 * j].decode(), "stop": names[2 * j + 1].decode()})
    return pd.DataFrame(rows, columns=["value", "qoi", "estimate", "se", "ci_lo", "ci_hi", "u_num", "n",
                                       "estimator", "stop"])


def evaluate(scene, design, unum=True):
    """The model at each row of `design` (a DataFrame, or anything
    pandas.DataFrame takes): its columns are scene keys (numeric), or
    l_over_R, or `realisation` (the row's field: the sweep's realisation
    i; without it row j uses realisation j).  Returns the design with the
    QoIs, their ratios, their u_num and a status column ("ok", or why the
    row failed: a failed row fails alone), as `slipfield evaluate`."""
    pd = _pandas()
    design = pd.DataFrame(design).reset_index(drop=True)
    out = []
    for j, row in design.iterrows():
        keys = {k: v for k, v in row.items() if k != "realisation"}
        real = int(row["realisation"]) if "realisation" in row else j
        rec = dict(row)
        try:
            with _Model(scene) as m:
                if "l_over_R" in keys and "R" in keys:   # l_over_R after R, as the CLI does
                    m.set("R", keys.pop("R"))
                for k, v in keys.items():
                    m.set(k, v)
                r = m.run(real, unum)
            rec.update({k: v for k, v in r.items() if k != "warning"})
            rec["status"] = "ok"
        except SlipfieldError as e:
            for name in QOIS:
                rec.update({name: math.nan, name + "_ratio": math.nan, "u_" + name: math.nan})
            rec["status"] = str(e)
        out.append(rec)
    return pd.DataFrame(out)


def results(path="reports/results.json"):
    """A verification run's results.json as one DataFrame: a row per check
    row (kind = "row": case, verdict, quantity, measured, expected,
    criterion, pass, ...) and per claim (kind = "claim": id, status,
    measured, ci_lo, ci_hi, alpha); the run's claim tally in .attrs."""
    import json
    pd = _pandas()
    with open(path) as f:
        d = json.load(f)
    recs = []
    for c in d.get("cases", []):
        base = {"case": c.get("id"), "verdict": c.get("verdict"), "tier": c.get("tier")}
        for r in c.get("rows", []):
            recs.append(dict(base, kind="row", **r))
        for cl in c.get("claims", []) or []:
            recs.append(dict(base, kind="claim", **cl))
    df = pd.DataFrame(recs)
    df.attrs["summary"] = d.get("summary")
    df.attrs["claims"] = d.get("claims")
    return df
