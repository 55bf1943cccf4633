/* slipfield: the whole public interface in one include,
 *     #include <slipfield/slipfield.h>
 * (pkg-config --cflags --libs slipfield).  Call sf_init() once before
 * anything else (sf_error.h).  Each header below can also be included on
 * its own; all of them can be included from C++ (extern "C"). */
#ifndef SF_SLIPFIELD_H
#define SF_SLIPFIELD_H

#include "sf_version.h"    /* SF_VERSION_MAJOR ..., sf_version() */
#include "sf_error.h"      /* error codes, sf_init(), exit statuses */
#include "scene.h"         /* scenes: key = value files, Table 1 defaults */
#include "lognormal.h"     /* lognormal marginals, the Nataf map */
#include "field.h"         /* Gaussian fields by circulant embedding */
#include "lnfield.h"       /* lognormal COF fields */
#include "tiles.h"         /* fields generated on demand in tiles */
#include "noise.h"         /* white noise fixed in belt coordinates */
#include "cellavg.h"       /* the cell-averaged COF field */
#include "cof.h"           /* the COF seen by the disc */
#include "contact.h"       /* the friction wrench, Eqs. 7-8 */
#include "surface.h"       /* the static limit surface, Eqs. 9-11 */
#include "numplan.h"       /* the accuracy-driven numerical plan */
#include "cycle1d.h"       /* the 1-D cycle in closed form, Eqs. 3-4 */
#include "oscillator.h"    /* the stick-slip integrators */
#include "qoi.h"           /* quantities of interest */
#include "montecarlo.h"    /* reproducible Monte Carlo */
#include "mcstop.h"        /* two-stage sample sizes (Stein) */
#include "sweep.h"         /* parameter sweeps */
#include "mlmc.h"          /* the two-level estimator of a sweep point */
#include "antithetic.h"    /* antithetic pairs: an estimator of a sweep point */
#include "sobol.h"         /* Sobol' indices by pick-freeze */
#include "sensitivity.h"   /* Sobol' indices of the QoI ratios */
#include "unum.h"          /* numerical error of a run's QoIs */
#include "model.h"         /* the high-level calls: a scene in, QoIs with u_num out */

#endif
