"""Moments of sampled outputs as the host computes them (host/sample_statistics.cpp), summed in the same
order so that they are the same doubles."""
import numpy as np


def weighted_moments(values, weights):
    """mean = sum_k w_k q_k (000:(3.10)), std = sqrt(max(sum_k w_k (q_k - mean)^2, 0)) (000:(3.11)) and how
    many variance entries came out negative (sparse-grid weights can be negative)."""
    mean = np.zeros_like(values[0], dtype=float)
    for w, q in zip(weights, values):
        mean += w * q
    variance = np.zeros_like(mean)
    for w, q in zip(weights, values):
        d = q - mean
        variance += w * d * d
    clamped = int(np.count_nonzero(variance < 0))
    return mean, np.sqrt(np.maximum(variance, 0.0)), clamped


def pce_std(values, projection):
    """Standard deviation of the sparse pseudo-spectral surrogate: sqrt of the sum of the squared
    non-constant coefficients."""
    count, terms = projection
    c = np.zeros((count,) + np.shape(values[0]))
    for coefficient, sample, factor in terms:
        c[coefficient] += factor * values[sample]
    total = np.zeros_like(c[0])
    for a in range(1, count):
        total += c[a] * c[a]
    return np.sqrt(total)


def standard_errors(values, mean, std):
    """Monte Carlo (equal weights): se(mean) = s/sqrt(Q), se(variance) = sqrt((m4 - m2^2)/Q),
    se(std) = se(variance)/(2 std); NaN for Q = 1."""
    q = float(len(values))
    m4 = np.zeros_like(mean)
    for v in values:
        d = v - mean
        m4 += d * d * d * d / q
    nan = np.full_like(mean, np.nan)
    if len(values) < 2:
        return nan, nan, nan.copy()
    m2 = std * std
    se_mean = np.sqrt(m2 * q / (q - 1) / q)
    se_variance = np.sqrt(np.maximum(m4 - m2 * m2, 0.0) / q)
    with np.errstate(divide="ignore", invalid="ignore"):
        se_std = np.where(std > 0, se_variance / (2 * std), np.nan)
    return se_mean, se_variance, se_std


def l2_distance(ax, ay, bx, by, h):
    """sqrt(h^2 sum_i |a_i - b_i|^2) over the two displacement components, summed in point order."""
    terms = ((ax - bx) * (ax - bx) + (ay - by) * (ay - by)).ravel()
    return float(np.sqrt(np.cumsum(terms)[-1] * h * h)) if terms.size else 0.0
