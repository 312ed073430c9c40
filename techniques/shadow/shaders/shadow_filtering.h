// Visibility functions of the shadow-filtering family (VSM, ESM, Gaussian and power CDF, EVSM,
// MSM) and the penumbra estimates, shared by the GLSL shaders and the C++ tests (shared_math.h).
// Include after shadow_common.h. SHADOW_FILTERING.md explains each function and its limits.
//
// Conventions, for every visibility function below:
//  * depths are canopy's normalised linear light depth z in [0, 1] (0 at the light's near plane);
//  * the result is a finite value in [0, 1] (1 = lit) for finite inputs, non-increasing in the
//    receiver depth z_r, and 1 for an unoccluded planar receiver (z_r at the filtered mean with
//    zero or tiny variance; MSM: 1 - O(moment_bias), see msm_hamburger_visibility);
//  * where a paper's formula divides by zero (zero variance, z_min = z_max, beta = 0 or infinite)
//    the limit is taken and documented at that spot.
#ifndef CANOPY_SHADOW_FILTERING_H
#define CANOPY_SHADOW_FILTERING_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST float SF_FLT_MAX = 3.402823466e38f;  // largest float
CANOPY_CONST float SF_FLT_MIN = 1.175494351e-38f; // smallest normal float
CANOPY_CONST float SF_TINY = 1e-30f;              // floor of denominators that are >= 0 in exact arithmetic

// ---------------------------------------------------------------------------------------------
// Helpers with no GLSL builtin: 1 - exp(y) and ln(1 - q) without cancellation near 0.

// 1 - exp(y) for y <= 0. Below |y| = 0.2 a 6-term Taylor series (truncation < 1.3e-8 relative)
// replaces 1 - exp(y), which loses all digits as y -> 0 (1 - exp(-1e-8) is 0 in float).
CANOPY_FN float sf_one_minus_exp(float y) {
    if (y > -0.2f) {
        return -y * (1.0f + y * (0.5f + y * (1.0f / 6.0f + y * (1.0f / 24.0f + y * (1.0f / 120.0f + y * (1.0f / 720.0f))))));
    }
    return 1.0f - exp(y);
}

// ln(1 - q) for q in [0, 1). Below q = 0.01 a 5-term series (truncation < 2e-11 relative), since
// 1 - q rounds away the digits of q (GLSL has no log1p).
CANOPY_FN float sf_log_one_minus(float q) {
    if (q < 0.01f) {
        return -q * (1.0f + q * (0.5f + q * (1.0f / 3.0f + q * (0.25f + q * 0.2f))));
    }
    return log(max(1.0f - q, SF_FLT_MIN));
}

// ln(a / (a + b)) for a, b >= 0, a + b = total > 0: log(a / total) while a is the smaller part,
// ln(1 - b / total) when a is close to the total (accurate near 1, where log(a/total) is not).
CANOPY_FN float sf_log_fraction(float a, float b, float total) {
    if (a <= b) return log(max(a / total, SF_FLT_MIN));
    return sf_log_one_minus(b / total);
}

// ---------------------------------------------------------------------------------------------
// VSM: one-tailed Chebyshev inequality (Donnelly & Lauritzen 2006; Gumbau 2011 eq 2.1-2.2).
//   moments = (E[z], E[z^2]); sigma^2 = E[z^2] - E[z]^2; p = sigma^2 / (sigma^2 + (z_r - mu)^2).
// Limits and guards:
//  * z_r <= mu -> 1 (eq 2.2's "fully lit"): a planar receiver at the mean is lit exactly;
//  * sigma^2 is clamped below by max(min_variance, 0): this also absorbs a negative variance from
//    cancellation (e.g. (0.5, 0.25 - 1e-9)); with sigma^2 = 0 the bound is the step 0 for z_r > mu
//    (the limit sigma^2 -> 0+), the denominator is floored so 0/0 cannot occur;
//  * infinite moments (a storage overflow, e.g. EVSM in fp16 above evsm_max_exponent) are read as
//    +-FLT_MAX, so the result stays finite; it is then meaningless but in [0, 1].
// Float rounding is monotone, so the result is exactly non-increasing in z_r.
CANOPY_FN float chebyshev_upper_bound(vec2 moments, float z_r, float min_variance) {
    float mean = clamp(moments.x, -SF_FLT_MAX, SF_FLT_MAX);
    if (z_r <= mean) return 1.0f;
    float m2 = clamp(moments.y, 0.0f, SF_FLT_MAX);
    float variance = max(m2 - mean * mean, max(min_variance, 0.0f));
    float d = z_r - mean;
    return clamp(variance / max(variance + d * d, SF_TINY), 0.0f, 1.0f);
}

// Lauritzen's light-bleeding reduction (GPU Gems 3, ch. 8): linstep(amount, 1, p), i.e. upper
// bounds below `amount` become 0 and [amount, 1] is stretched to [0, 1]. Non-decreasing in p and
// 1 -> 1, so it keeps every property above. amount is clamped to [0, 0.9999] (amount = 1 would
// divide by zero; negative amounts mean no reduction).
CANOPY_FN float reduce_light_bleeding(float p, float amount) {
    float a = clamp(amount, 0.0f, 0.9999f);
    return clamp((p - a) / (1.0f - a), 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// ESM (Annen et al. 2008; Salvi 2008): visibility = E[exp(c z)] * exp(-c z_r), clamped to 1.
// Both forms evaluate exp(min(ln E[exp(c z)] - c z_r, 0)), so the clamp to 1 happens before the
// exponential (no overflow) and the result is exactly non-increasing in z_r for c >= 0.
// The exponent is also floored at -87 (exp(-87) = 1.6e-38, just above the smallest normal float).
// Linear storage overflows when c z > ln(FLT_MAX) = 88.72 (fp32) or ln(65504) = 11.09 (fp16):
// an infinite stored value is read as FLT_MAX (ln = 88.72), which keeps the result finite and
// monotone but not meaningful -- keep c below those bounds, or use log storage.
// Largest exponent c whose linear storage exp(c z), z in [0, 1], cannot overflow: fp16 holds up to
// 65504 = e^11.09 -> 11; fp32 up to 3.4e38 = e^88.72, and the box prefilter sums up to 63 texels
// before dividing (63 = e^4.14) -> 84. shadow.esm refuses larger exponents with linear storage.
CANOPY_CONST float ESM_MAX_EXPONENT_FP16 = 11.0f;
CANOPY_CONST float ESM_MAX_EXPONENT_FP32 = 84.0f;
CANOPY_FN float esm_max_exponent(bool half_precision) {
    return half_precision ? ESM_MAX_EXPONENT_FP16 : ESM_MAX_EXPONENT_FP32;
}

CANOPY_FN float esm_visibility_log(float filtered_log, float z_r, float c) {
    float e = clamp(filtered_log - c * z_r, -87.0f, 0.0f);
    return exp(e);
}

CANOPY_FN float esm_visibility(float filtered_exp, float z_r, float c) {
    return esm_visibility_log(log(clamp(filtered_exp, SF_FLT_MIN, SF_FLT_MAX)), z_r, c);
}

// log(wa e^a + wb e^b) for weights >= 0 without overflow (the log-space ESM filter, Salvi 2008):
// m + log(wa e^(a-m) + wb e^(b-m)) with m the larger log among terms of positive weight. A
// zero-weight term is dropped (otherwise its log could set m and underflow the sum); with both
// weights zero the sum is floored at FLT_MIN (result b - 87.3) instead of log(0) = -inf.
CANOPY_FN float log_sum_exp_weighted(float log_a, float weight_a, float log_b, float weight_b) {
    if (!(weight_a > 0.0f)) return log_b + log(max(weight_b, SF_FLT_MIN));
    if (!(weight_b > 0.0f)) return log_a + log(weight_a);
    float m = max(log_a, log_b);
    return m + log(max(weight_a * exp(log_a - m) + weight_b * exp(log_b - m), SF_FLT_MIN));
}

// ---------------------------------------------------------------------------------------------
// Bilinear lookups combined in a technique's own space. The lit pass fetches the four texels a
// LINEAR lookup would blend (bilinear_texels.glsl) and combines them here, where hardware
// filtering would blend the wrong quantity. Texel order (x, y) = (0, 0), (1, 0), (0, 1), (1, 1);
// f is the lookup's fraction between them, in [0, 1]^2.

// The weights of a LINEAR lookup at fraction f, in texel order; they sum to 1.
CANOPY_FN vec4 bilinear_weights(vec2 f) {
    return vec4((1.0f - f.x) * (1.0f - f.y), f.x * (1.0f - f.y), (1.0f - f.x) * f.y, f.x * f.y);
}

// Log-space ESM: the texels hold ln E[exp(c z)] of their prefilter window; the lookup must blend
// the exponentials, log(sum w_i e^(l_i)), not the logs (which is a geometric mean: it drops an
// edge's lit side from e^(c z_far) to e^(c (z_near + z_far) / 2)). Evaluated relative to the
// largest log of positive weight (Salvi 2008), so nothing overflows for any c; a zero-weight texel
// is ignored, however large its log.
CANOPY_FN float esm_log_bilinear(vec4 logs, vec2 f) {
    vec4 w = bilinear_weights(clamp(f, vec2(0.0f), vec2(1.0f)));
    float m = -SF_FLT_MAX;
    for (int i = 0; i < 4; ++i) if (w[i] > 0.0f) m = max(m, logs[i]);
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i) if (w[i] > 0.0f) sum += w[i] * exp(logs[i] - m);
    return m + log(max(sum, SF_FLT_MIN));
}

// Power CDF: each texel holds (min, max, mean) of its window. The lookup's mean is the bilinear
// blend of the windows' means; its min and max are those of every window that blend weighs
// (positive weight), so they bound every depth the mean averages -- blending the mins and maxes
// too would give neither a min nor a max. Returns (z_min, z_max, mean).
CANOPY_FN vec3 power_cdf_bilinear_statistics(vec3 t00, vec3 t10, vec3 t01, vec3 t11, vec2 f) {
    vec4 w = bilinear_weights(clamp(f, vec2(0.0f), vec2(1.0f)));
    float mean = w.x * t00.z + w.y * t10.z + w.z * t01.z + w.w * t11.z;
    float lo = SF_FLT_MAX, hi = -SF_FLT_MAX;
    if (w.x > 0.0f) { lo = min(lo, t00.x); hi = max(hi, t00.y); }
    if (w.y > 0.0f) { lo = min(lo, t10.x); hi = max(hi, t10.y); }
    if (w.z > 0.0f) { lo = min(lo, t01.x); hi = max(hi, t01.y); }
    if (w.w > 0.0f) { lo = min(lo, t11.x); hi = max(hi, t11.y); }
    return vec3(lo, hi, mean);
}

// ---------------------------------------------------------------------------------------------
// Error functions (GLSL has no erf).

// Winitzki 2008, as printed in Gumbau eq 7.3:
//   erf(x) ~ sign(x) sqrt(1 - exp(-x^2 (4/pi + a x^2) / (1 + a x^2))), a = 8(pi-3)/(3 pi (4-pi)).
// Measured in float against std::erf (../tests/test_shadow_filtering.cpp): max |error| 3.3e-4
// (absolute, at |x| = 1.35), max relative error 3.5e-4; exact at 0 and +-inf. 1 - exp(-y)
// uses sf_one_minus_exp so erf(x) ~ 2x/sqrt(pi) keeps its digits for small x. |x| is capped at
// 10, where erf is 1 in float, so x^2 cannot overflow into inf/inf.
CANOPY_CONST float WINITZKI_A = 0.1400122886866665f;
CANOPY_FN float erf_winitzki(float x) {
    float ax = min(abs(x), 10.0f);
    float x2 = ax * ax;
    float y = x2 * (1.2732395447351628f + WINITZKI_A * x2) / (1.0f + WINITZKI_A * x2);  // 4/pi
    return sign(x) * sqrt(clamp(sf_one_minus_exp(-y), 0.0f, 1.0f));
}

// An erf accurate to float precision: measured max |error| 1.6e-7 against std::erf over
// [-6, 6] (../tests/test_shadow_filtering.cpp), and non-decreasing. Abramowitz & Stegun 7.1.26
// (|error| <= 1.5e-7 in exact arithmetic) reaches 2.5e-7 once evaluated in float, because
// 1 - (a value near 1) keeps the rounding of the polynomial, so two pieces are used instead:
//  * |x| < 0.75: the Maclaurin series (2/sqrt(pi)) sum_{n=0..8} (-1)^n x^(2n+1) / (n! (2n+1))
//    (truncation < 2e-9 there; no cancellation since the terms shrink fast);
//  * |x| >= 0.75: 1 - erfc(x) with the Chebyshev fit of Press et al., Numerical Recipes
//    (erfcc, fractional error < 1.2e-7 in erfc, which is <= 0.29 here).
// The two pieces agree to the last bit at 0.75 (no step). Odd; erf(0) = 0; +-inf -> +-1 (|x| is
// capped at 10, where erfc is 2e-45).
CANOPY_FN float erf_accurate(float x) {
    float ax = min(abs(x), 10.0f);
    if (ax < 0.75f) {
        float x2 = x * x;
        float series = 1.0f + x2 * (-1.0f / 3.0f + x2 * (0.1f + x2 * (-1.0f / 42.0f + x2 * (1.0f / 216.0f +
                       x2 * (-1.0f / 1320.0f + x2 * (1.0f / 9360.0f + x2 * (-1.0f / 75600.0f + x2 * (1.0f / 685440.0f))))))));
        return 1.1283791670955126f * x * series;  // 2 / sqrt(pi)
    }
    float t = 1.0f / (1.0f + 0.5f * ax);
    float p = -ax * ax - 1.26551223f + t * (1.00002368f + t * (0.37409196f + t * (0.09678418f + t * (-0.18628806f +
              t * (0.27886807f + t * (-1.13520398f + t * (1.48851587f + t * (-0.82215223f + t * 0.17087277f))))))));
    return sign(x) * (1.0f - t * exp(p));
}

// ---------------------------------------------------------------------------------------------
// Gaussian CDF (Gumbau 2011 eq 7.1-7.4): the depth distribution taken as N(mu, sigma^2) and the
// visibility biased so that the mean is lit (eq 7.1-7.2):
//   v = (1 - F(z_r)) / (1 - F(mu)) = 1 - erf((z_r - mu) / (sigma sqrt 2)) for z_r > mu, else 1.
// Limits: sigma^2 is clamped as in chebyshev_upper_bound; eq 7.4 divides by sigma, so sigma is
// floored at 1e-20: with zero variance the argument is >= 1e20 |z_r - mu| and the result is the
// step 0 for z_r > mu -- the limit sigma -> 0+. exact_erf picks erf_accurate over erf_winitzki.
CANOPY_FN float gaussian_cdf_visibility(vec2 moments, float z_r, float min_variance, bool exact_erf) {
    float mean = clamp(moments.x, -SF_FLT_MAX, SF_FLT_MAX);
    if (z_r <= mean) return 1.0f;
    float m2 = clamp(moments.y, 0.0f, SF_FLT_MAX);
    float variance = max(m2 - mean * mean, max(min_variance, 0.0f));
    float x = (z_r - mean) / max(sqrt(2.0f * variance), 1e-20f);
    float e = exact_erf ? erf_accurate(x) : erf_winitzki(x);
    return clamp(1.0f - e, 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// Power CDF (Gumbau 2011 eq 7.5-7.7): F(z) = t^beta, t = (z - z_min) / dz, dz = z_max - z_min,
// beta = (mu - z_min) / (z_max - mu) (eq 7.6, so that F has mean mu), and
//   v = (1 - t^beta) / (1 - t_mu^beta), t_mu = beta / (beta + 1), for z_r > mu, else 1.  (7.7)
// Evaluated as (1 - exp(beta ln t)) / (1 - exp(beta ln t_mu)) with sf_one_minus_exp and
// ln t from whichever of (z - z_min) and (z_max - z) is smaller, so neither end loses digits.
// Limits and guards, in order:
//  * inputs out of order (from rounding or filtering) are repaired: z_min/z_max swapped if
//    inverted, mu clamped into [z_min, z_max];
//  * z_r <= mu -> 1 (eq 7.7 "1 otherwise"); this is also the front side of dz = 0;
//  * z_r >= z_max -> 0 (t >= 1, F = 1): every filtered depth is in front. This is the back side of
//    dz = 0 (a clean step at the single depth) and the whole beta -> inf case (mu = z_max leaves
//    no receiver depth between mu and z_max);
//  * beta -> 0 (mu = z_min, all mass at z_min): 0 for z_r > mu. The limit of eq 7.7 at fixed
//    t in (0, 1) is ln t / ln beta -> 0 (slowly); below beta = 1e-30 the products beta ln t would
//    approach the denormal range, so that band returns the limit 0;
//  * beta ln t is formed as (mu - z_min) ln t / (z_max - mu), which stays finite as beta -> inf
//    (there beta ln t_mu -> -1 and v -> (1 - e^-(1-u)) / (1 - e^-1), u the receiver's fraction of
//    the way from mu to z_max).
CANOPY_FN float power_cdf_visibility(float z_min, float z_max, float mean, float z_r) {
    float lo = min(z_min, z_max);
    float hi = max(z_min, z_max);
    float mu = clamp(mean, lo, hi);
    if (z_r <= mu) return 1.0f;
    if (z_r >= hi) return 0.0f;
    float below = mu - lo;                    // dz t_mu
    float above = max(hi - mu, SF_FLT_MIN);   // dz (1 - t_mu) > 0 since mu < z_r < hi
    if (below <= 1e-30f * above) return 0.0f; // beta -> 0
    float dz = hi - lo;
    float ln_t = sf_log_fraction(z_r - lo, hi - z_r, dz);
    float ln_t_mean = sf_log_fraction(below, above, dz);
    float num = sf_one_minus_exp(below * ln_t / above);       // 1 - t^beta
    float den = sf_one_minus_exp(below * ln_t_mean / above);  // 1 - t_mu^beta > 0
    return clamp(num / max(den, SF_TINY), 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// EVSM (Lauritzen & McCool 2008): Chebyshev on exponentially warped depths. z is mapped to
// z' = 2z - 1 in [-1, 1] (clamped there) and warped to p = exp(c_pos z'), n = -exp(-c_neg z');
// both are increasing in z. Exponents are clamped to [0, evsm_max_exponent(false)] so p, n and
// their squares are finite in fp32; the caller clamps to evsm_max_exponent(true) for fp16 maps.

// Largest exponent c with exp(c)^2 storable: fp16 ln(65504)/2 = 5.545 -> 5.54; fp32
// ln(3.4e38)/2 = 44.36 -> 42, leaving a margin of e^4.7 for sums of filter weights > 1.
CANOPY_CONST float EVSM_MAX_EXPONENT_FP16 = 5.54f;
CANOPY_CONST float EVSM_MAX_EXPONENT_FP32 = 42.0f;
CANOPY_FN float evsm_max_exponent(bool half_precision) {
    return half_precision ? EVSM_MAX_EXPONENT_FP16 : EVSM_MAX_EXPONENT_FP32;
}

CANOPY_FN vec2 evsm_warp(float z, float c_pos, float c_neg) {
    float zz = clamp(2.0f * z - 1.0f, -1.0f, 1.0f);
    float cp = clamp(c_pos, 0.0f, EVSM_MAX_EXPONENT_FP32);
    float cn = clamp(c_neg, 0.0f, EVSM_MAX_EXPONENT_FP32);
    return vec2(exp(cp * zz), -exp(-cn * zz));
}

CANOPY_FN vec4 evsm_moments(float z, float c_pos, float c_neg) {
    vec2 w = evsm_warp(z, c_pos, c_neg);
    return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}

// Chebyshev bound of one warp (Lauritzen & McCool 2008) with receiver warp w_r and exponent c.
// min_variance is in depth units (z^2, as for VSM) and mapped through the warp's slope at the
// receiver, dw/dz = 2 c |w_r| (as MJP's sample scales it), so the floor is
// (2c)^2 min_variance w_r^2 in warped units: with a large c the warp is far from linear over
// sqrt(min_variance), and a receiver delta behind a single depth gets
// k / (k + (1 - e^(-2c delta))^2), k = (2c)^2 min_variance -- more than VSM's floor would give.
// Since Chebyshev's bound grows with the variance, max(variance, floor) is evaluated as the larger
// of two bounds:
//  * the data's, var / (var + d^2), on the warped axis divided by the moments' own scale
//    s = sqrt(E[w^2]). The ratio does not change with the unit, and in that unit E[w^2] = 1,
//    E[w]^2 <= 1 and the variance is O(1): evaluated in raw warped units, a footprint near z = 0
//    with c = 40 has var + d^2 ~ e^-73 (1e-32), below any fixed floor of the denominator (a floor
//    of 1e-30 turned an edge half at z = 0, half at 0.05, receiver at 0.05, from 0.5 into 0.21).
//    s does not depend on z_r, so the receiver's term w_r / s is monotone in z_r;
//  * the floor's, k / (k + q^2) with q = d / |w_r| = sign(w_r) - mean / |w_r|.
// Each is exactly non-increasing in z_r in float (every operation is monotone in z_r), so the
// result is too. Scaled values stay finite: |w| <= e^42 and s >= |E[w]| >= e^-42 for a valid
// footprint, so w_r / s <= e^84 < FLT_MAX; a d^2 that overflows to inf gives the limit 0.
// Infinite moments (fp16 overflow) are read as +-FLT_MAX as in chebyshev_upper_bound, and a zero
// E[w^2] (invalid, e.g. underflow) is floored at FLT_MIN.
CANOPY_FN float sf_evsm_bound(vec2 moments, float w_r, float c, float min_variance) {
    float mean = clamp(moments.x, -SF_FLT_MAX, SF_FLT_MAX);
    if (w_r <= mean) return 1.0f;
    float scale = sqrt(clamp(moments.y, SF_FLT_MIN, SF_FLT_MAX));  // sqrt(E[w^2])
    float mean_scaled = mean / scale;                              // |.| <= 1 for valid moments
    float variance_scaled = max((1.0f - mean_scaled) * (1.0f + mean_scaled), 0.0f);  // less cancellation than 1 - m^2
    float d_scaled = w_r / scale - mean_scaled;
    float p_data = variance_scaled / max(variance_scaled + d_scaled * d_scaled, SF_TINY);
    float slope = 2.0f * c;
    float k = max(min_variance, 0.0f) * slope * slope;
    float q = (w_r > 0.0f ? 1.0f : -1.0f) - mean / abs(w_r);  // |w_r| >= exp(-42) > 0
    float p_floor = k / max(k + q * q, SF_TINY);
    return clamp(max(p_data, p_floor), 0.0f, 1.0f);
}

// 2 components: positive warp only. positive_moments = (E[p], E[p^2]).
CANOPY_FN float evsm2_visibility(vec2 positive_moments, float z_r, float c_pos, float min_variance) {
    float cp = clamp(c_pos, 0.0f, EVSM_MAX_EXPONENT_FP32);
    vec2 w = evsm_warp(z_r, cp, 0.0f);
    return sf_evsm_bound(positive_moments, w.x, cp, min_variance);
}

// 4 components: the smaller of the positive and negative bounds. moments = (E[p], E[p^2], E[n], E[n^2]).
CANOPY_FN float evsm4_visibility(vec4 moments, float z_r, float c_pos, float c_neg, float min_variance) {
    float cp = clamp(c_pos, 0.0f, EVSM_MAX_EXPONENT_FP32);
    float cn = clamp(c_neg, 0.0f, EVSM_MAX_EXPONENT_FP32);
    vec2 w = evsm_warp(z_r, cp, cn);
    float pos = sf_evsm_bound(vec2(moments.x, moments.y), w.x, cp, min_variance);
    float neg = sf_evsm_bound(vec2(moments.z, moments.w), w.y, cn, min_variance);
    return min(pos, neg);
}

// ---------------------------------------------------------------------------------------------
// MSM: moment shadow mapping with four moments and the Hamburger reconstruction (Peters & Klein
// 2015, "Moment Shadow Mapping", I3D; Algorithm 3 and the optimised quantisation of sec. 4, as in
// the authors' and MJP's public code: Compute4MomentUnboundedShadowIntensity,
// GetOptimizedMoments/ConvertOptimizedMoments in TheRealMJP/Shadows MSM.hlsl).

// Optimised quantisation: b* = M (z, z^2, z^3, z^4) + (0.035955884801, 0, 0, 0); every stored
// component lies in about [0, 1] for z in [0, 1] (rgba16 unorm or rgba16f). Written as one dot
// product per output row of M.
CANOPY_FN vec4 msm_encode(float z) {
    float z2 = z * z;
    vec4 b = vec4(z, z2, z2 * z, z2 * z2);
    return vec4(dot(vec4(-2.07224649f, 32.23703778f, -68.571074599f, 39.3703274134f), b) + 0.035955884801f,
                dot(vec4(13.7948857237f, -59.4683975703f, 82.0359750338f, -35.364903257f), b),
                dot(vec4(0.105877704f, -1.9077466311f, 9.3496555107f, -6.6543490743f), b),
                dot(vec4(9.7924062118f, -33.7652110555f, 47.9456096605f, -23.9728048165f), b));
}

// Inverse: b = M^-1 (b* - (0.035955884801, 0, 0, 0)).
CANOPY_FN vec4 msm_decode(vec4 stored) {
    vec4 s = vec4(stored.x - 0.035955884801f, stored.y, stored.z, stored.w);
    return vec4(dot(vec4(0.2227744146f, 0.0771972861f, 0.7926986636f, 0.0319417555f), s),
                dot(vec4(0.1549679261f, 0.1394629426f, 0.7963415838f, -0.1722823173f), s),
                dot(vec4(0.1451988946f, 0.2120202157f, 0.7258694464f, -0.2758014811f), s),
                dot(vec4(0.163127443f, 0.2591432266f, 0.6539092497f, -0.3376131734f), s));
}

// Clamp of n / d to [-limit, limit] without forming inf or NaN (d = 0 allowed).
CANOPY_FN float sf_bounded_div(float n, float d, float limit) {
    if (abs(n) >= limit * abs(d)) return sign(n) * (d < 0.0f ? -limit : limit);
    return n / d;
}

// Shadow intensity G = the sharpest lower bound of P(z < z_r) over all distributions (on the
// real line) with the moments b = (b1..b4): the canonical representation with an atom at z_r and
// two more atoms z1 <= z2 at the roots of c2 z^2 + c1 z + c0, where c solves B c = (1, z_r, z_r^2)
// for the Hankel matrix B of (1, b1..b4) (Cholesky, as in Algorithm 3); G sums the weights of the
// atoms strictly below z_r. Returns 1 - G.
// Bias: b' = (1 - alpha) b + alpha b_target. Peters & Klein (2015) blend towards (0.5, 0.5, 0.5,
// 0.5), the moments of half the mass at 0 and half at 1: that target lies on the boundary of the
// moment space, so blended with a single depth at exactly 0 or 1 (a cleared far plane!) B stays
// singular and the Cholesky step divides 0 by 0. canopy uses the target of Peters et al.'s later
// code (JCGT 2017 demo, Convert4MomentOptimizedToCanonical: (0, 0.628, 0, 0.628) for depths mapped
// to [-1, 1]) expressed for z in [0, 1]: b_target = (0.5, 0.407, 0.3605, 0.33725), the moments of
// masses 0.314, 0.372, 0.314 at z = 0, 1/2, 1. Three atoms make its Hankel matrix positive
// definite, so B' is for every valid b. (Blending is linear and the map from [-1, 1] moments to
// [0, 1] moments is affine, so this is exactly their bias.) It is also the best conditioned of
// the targets tried. The result should not rise with z_r, but float rounding in the solve makes
// it dip just behind an atom (a band ~1e-4 wide in z). Worst step up, measured by
// test_shadow_filtering.cpp ("MSM: measured rise"; fine sweeps around every atom of ~1300
// footprints) and asserted there: fp32 moments, alpha 3e-5: 4.2e-5 (bound 1e-4); unorm16,
// alpha 6e-5: 4.8e-5 (bound 1e-4). With the uniform distribution's moments as target: 1.5e-4
// and 0.10; with (0.5, 0.5, 0.5, 0.5): 1.0e-4 and 0.016.
// alpha: ~3e-5 for fp32 moments, ~6e-5 for 16-bit unorm (the paper's values); unorm16 with 3e-5
// rises by 0.014 in the test (0.29 in a wider search). Half floats (rgba16f) keep only 11 bits
// over [0.5, 1]: the result rises by up to 0.55 in the test (0.85 in a wider search) -- no
// longer monotone in any useful sense: use rgba16 unorm for MSM.
// A planar receiver (a single depth at z_r) gets 1 - G with G <= alpha (G is a lower bound for
// every distribution with these moments, the biased one included, and the target puts at most
// 0.686 of its mass below z_r); the usual remedy is a small depth bias subtracted from z_r.
// Guards (only reachable with invalid moments, e.g. from 16-bit rounding, or alpha ~ 0): the
// Cholesky pivots are floored (D22 >= 1e-10, D33 D22 >= 1e-20), c is normalised before solving
// the quadratic, the roots come from the cancellation-free form and are clamped to +-1e6 (an atom
// out there carries weight O(1e-6)), and z_r is clamped to [-1, 2]: the result is always finite.
CANOPY_FN float msm_hamburger_visibility(vec4 moments, float z_r, float moment_bias) {
    float alpha = clamp(moment_bias, 0.0f, 1.0f);
    vec4 b = mix(moments, vec4(0.5f, 0.407f, 0.3605f, 0.33725f), alpha);
    float z0 = clamp(z_r, -1.0f, 2.0f);

    // Cholesky factorisation of B storing only the non-trivial entries.
    float l32_d22 = b.z - b.x * b.y;
    float d22 = max(b.y - b.x * b.x, 1e-10f);
    float squared_variance = b.w - b.y * b.y;
    float d33_d22 = max(squared_variance * d22 - l32_d22 * l32_d22, 1e-20f);
    float inv_d22 = 1.0f / d22;
    float l32 = l32_d22 * inv_d22;

    // Solve B c = (1, z0, z0^2): forward substitution, scaling, backward substitution.
    float c0 = 1.0f;
    float c1 = z0 - b.x;
    float c2 = z0 * z0 - b.y - l32 * c1;
    c1 *= inv_d22;
    c2 *= d22 / d33_d22;
    c1 -= l32 * c2;
    c0 -= c1 * b.x + c2 * b.y;
    float scale = 1.0f / max(max(abs(c0), abs(c1)), max(abs(c2), SF_TINY));
    c0 *= scale;
    c1 *= scale;
    c2 *= scale;

    // Roots of c2 z^2 + c1 z + c0 without cancellation: h = -(c1 + sign(c1) sqrt(disc)) / 2,
    // roots h / c2 and c0 / h.
    float root_disc = sqrt(max(c1 * c1 - 4.0f * c0 * c2, 0.0f));
    float h = -0.5f * (c1 + (c1 < 0.0f ? -root_disc : root_disc));
    float ra = sf_bounded_div(h, c2, 1e6f);
    float rb = sf_bounded_div(c0, h, 1e6f);
    float z1 = min(ra, rb);
    float z2 = max(ra, rb);

    float g = 0.0f;
    if (z2 < z0) {
        // z1 <= z2 < z0: G = 1 - w0, w0 = (z1 z2 - b1 (z1 + z2) + b2) / ((z0 - z1)(z0 - z2)).
        float num = (z1 - b.x) * z2 + (b.y - b.x * z1);
        g = 1.0f - num / max((z0 - z1) * (z0 - z2), SF_TINY);
    } else if (z1 < z0) {
        // z1 < z0 <= z2: G = w1 = (z0 z2 - b1 (z0 + z2) + b2) / ((z2 - z1)(z0 - z1)).
        float num = (z0 - b.x) * z2 + (b.y - b.x * z0);
        g = num / max((z2 - z1) * (z0 - z1), SF_TINY);
    }
    return 1.0f - clamp(g, 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// Penumbra estimates (parallel planes; Fernando 2005 as Gumbau 2011 eq 6.1, and eq 6.2).
// Distances are to the light (and the observer) in any one unit; w_light in the units wanted.
// Limits: a receiver in front of the blocker has no penumbra (0); d_blocker -> 0 would make the
// width infinite, so d_blocker is floored at 1e-6 d_receiver (width <= 1e6 w_light); w_light is
// clamped to [0, 1e20] and d_observer floored at 1e-6 (same unit), so results stay finite.
CANOPY_FN float pcss_penumbra_width(float d_receiver, float d_blocker, float w_light) {
    float gap = max(d_receiver - d_blocker, 0.0f);
    float blocker = max(d_blocker, max(1e-6f * d_receiver, SF_TINY));
    return clamp(w_light, 0.0f, 1e20f) * (gap / blocker);
}

// Eq 6.2: the penumbra width of eq 6.1 divided by the distance to the observer (its depth along
// the view axis, see ssss_sigma_pixels), for a filter applied in screen space (a kernel shrinks
// with distance).
CANOPY_FN float ssss_screen_penumbra_width(float d_receiver, float d_blocker, float w_light, float view_depth) {
    return pcss_penumbra_width(d_receiver, d_blocker, w_light) / max(view_depth, 1e-6f);
}

CANOPY_END_NAMESPACE

#endif
