// libslipfield from C++: the umbrella header, the version, and a wrench.
// Build it with
//   c++ consumer.cpp $(pkg-config --cflags --libs slipfield) -o consumer
#include <slipfield/slipfield.h>
#include <cmath>
#include <cstdio>
#include <cstring>

int main()
{
    sf_init();   // once, first: GSL errors are returned, not abort()ed on
    if (std::strcmp(sf_version(), SF_VERSION_STRING) != 0) {
        std::fprintf(stderr, "consumer: headers %s, library %s\n", SF_VERSION_STRING, sf_version());
        return 1;
    }
    sf_scene s;
    sf_scene_default(&s);   // Table 1
    sf_cof *cof = nullptr;
    sf_contact *ct = nullptr;
    if (sf_cof_alloc_uniform(s.mu_mean, &cof))
        return 1;
    sf_contact_spec spec = { s.R, s.m * s.g, SF_LAYOUT_POLAR, 16 };
    double q[3];
    int rc = sf_contact_alloc(&spec, cof, &ct);
    if (!rc)   // pure sliding along -x: the force is mu N against the slip
        rc = sf_contact_wrench(ct, 0, 0, -s.v_b, 0, 0, 1.0, q);
    sf_contact_free(ct);
    sf_cof_free(cof);
    double want = s.mu_mean * s.m * s.g;
    if (rc || std::fabs(q[0] - want) > 1e-9 * want) {
        std::fprintf(stderr, "consumer: rc %d, Fx %g, want %g\n", rc, rc ? 0.0 : q[0], want);
        return 1;
    }
    std::printf("slipfield %s from C++: Fx = %.6f N (mu N = %.6f N)\n", sf_version(), q[0], want);
    return 0;
}
