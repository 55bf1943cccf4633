/* slipfield (private, not installed): the AVX-512 look-up of the COF view
 * at 8 points and the AVX2 one at 4, for the wrench's on-grid loops
 * (contact.c) and its bench.
 * Kept out of cof.h so that the installed headers need no <immintrin.h>
 * and no target attributes (a C++ or non-x86 consumer includes them). */
#ifndef SF_COF_X512_H
#define SF_COF_X512_H

#include "cof.h"

/* The same look-up for 8 points at once, AVX-512 (the wrench's on-grid
 * loop on machines that have it; GCC or Clang on x86-64, and not in the
 * coverage build, -DSF_NO_CLONES, which compiles the portable loop only).
 * Lane by lane the operations of sf_cof_view_eval_on, in its order (the
 * same bits); what differs is how the nodal values arrive: a compiler
 * vectorising sf_cof_view_cell loads them one by one (4 scalar loads and
 * their inserts per point: about two thirds of the wrench's time on AVX-512
 * hardware without fast gathers), here (g[k], g[k+1]) and
 * (g[k+m], g[k+m+1]) come as two 16-byte loads per point and two unpacks
 * per 8 points sort them into g0..g3. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(SF_NO_CLONES)
#define SF_COF_VIEW_X512 1
#include <immintrin.h>

/* What the AVX-512 and AVX2 look-ups share, written once for the width
 * whose intrinsics' prefix is P (_mm512_ or _mm256_) and vector type T:
 * the grid coordinates (sf_cof_view_gx, _gy) of the points (xb, yb), and
 * the bilinear tail of sf_cof_view_cell from the row pairs e0, o0 (row j:
 * (g[k], g[k+1]) of the even and the odd points) and e1, o1 (row j + 1),
 * which two unpacks per row sort into g0..g3 point by point. */
#define SF_COF_GRID_XY(P, T, v, xb, yb, sx, sy)                                     \
    T sx = P##mul_pd(P##sub_pd(xb, P##set1_pd((v)->x0)), P##set1_pd((v)->idx));    \
    T sy = P##mul_pd(P##sub_pd(yb, P##set1_pd((v)->y0)), P##set1_pd((v)->idy))
#define SF_COF_BILINEAR(P, T, e0, o0, e1, o1, tx, ty, out)                          \
    do {                                                                           \
        T g0_ = P##unpacklo_pd(e0, o0), g1_ = P##unpackhi_pd(e0, o0);              \
        T g2_ = P##unpacklo_pd(e1, o1), g3_ = P##unpackhi_pd(e1, o1);              \
        T a_ = P##add_pd(g0_, P##mul_pd(tx, P##sub_pd(g1_, g0_)));                 \
        T b_ = P##add_pd(g2_, P##mul_pd(tx, P##sub_pd(g3_, g2_)));                 \
        (out) = P##add_pd(a_, P##mul_pd(ty, P##sub_pd(b_, a_)));                   \
    } while (0)

/* rows (g[k], g[k+1]) of points p0, p2, p4, p6 in one register */
__attribute__((target("avx512f"), always_inline)) static inline __m512d sf_cof_pairs4(const double *g, const int *k)
{
    __m256d lo = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(g + k[0])), _mm_loadu_pd(g + k[2]), 1);
    __m256d hi = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(g + k[4])), _mm_loadu_pd(g + k[6]), 1);
    return _mm512_insertf64x4(_mm512_castpd256_pd512(lo), hi, 1);
}

__attribute__((target("avx512f"), always_inline)) static inline __m512d sf_cof_view_eval_on8(const sf_cof_view *v,
                                                                                            __m512d xb, __m512d yb)
{
    SF_COF_GRID_XY(_mm512_, __m512d, v, xb, yb, sx, sy);
    __m256i i = _mm512_cvttpd_epi32(sx), j = _mm512_cvttpd_epi32(sy);   /* (int): truncation */
    __m512d tx = _mm512_sub_pd(sx, _mm512_cvtepi32_pd(i)), ty = _mm512_sub_pd(sy, _mm512_cvtepi32_pd(j));
    int k[8];
    _mm256_storeu_si256((__m256i *)(void *)k, _mm256_add_epi32(i, _mm256_mullo_epi32(_mm256_set1_epi32(v->m), j)));
    const double *g = v->grid, *h = v->grid + v->m;
    __m512d e0 = sf_cof_pairs4(g, k), o0 = sf_cof_pairs4(g, k + 1);   /* points 0 2 4 6 and 1 3 5 7 */
    __m512d e1 = sf_cof_pairs4(h, k), o1 = sf_cof_pairs4(h, k + 1), mu;
    SF_COF_BILINEAR(_mm512_, __m512d, e0, o0, e1, o1, tx, ty, mu);
    return mu;
}

/* The same look-up for 4 points, AVX2 (the wrench's on-grid loop on
 * machines without AVX-512): lane by lane sf_cof_view_eval_on's
 * operations in its order (the same bits; target avx2 without fma, so no
 * product is fused into a sum), the nodal values by pairs as above:
 * (g[k], g[k+1]) and (g[k+m], g[k+m+1]) as two 16-byte loads per point,
 * sorted into g0..g3 by two unpacks per row. */
__attribute__((target("avx2"), always_inline)) static inline __m256d sf_cof_pairs2(const double *g, const int *k)
{
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(g + k[0])), _mm_loadu_pd(g + k[2]), 1);
}

__attribute__((target("avx2"), always_inline)) static inline __m256d sf_cof_view_eval_on4(const sf_cof_view *v,
                                                                                         __m256d xb, __m256d yb)
{
    SF_COF_GRID_XY(_mm256_, __m256d, v, xb, yb, sx, sy);
    __m128i i = _mm256_cvttpd_epi32(sx), j = _mm256_cvttpd_epi32(sy);   /* (int): truncation */
    __m256d tx = _mm256_sub_pd(sx, _mm256_cvtepi32_pd(i)), ty = _mm256_sub_pd(sy, _mm256_cvtepi32_pd(j));
    int k[4];
    _mm_storeu_si128((__m128i *)(void *)k, _mm_add_epi32(i, _mm_mullo_epi32(_mm_set1_epi32(v->m), j)));
    const double *g = v->grid, *h = v->grid + v->m;
    __m256d e0 = sf_cof_pairs2(g, k), o0 = sf_cof_pairs2(g, k + 1);   /* points 0 2 and 1 3 */
    __m256d e1 = sf_cof_pairs2(h, k), o1 = sf_cof_pairs2(h, k + 1), mu;
    SF_COF_BILINEAR(_mm256_, __m256d, e0, o0, e1, o1, tx, ty, mu);
    return mu;
}
#endif

#endif
