"""The host's sample plans (host/sampling/), reproduced operation for operation so that the nodes and
weights are the same doubles: Gauss-Hermite and Gauss-Legendre rules in long double, tensor grids, Smolyak
sparse grids with their pseudo-spectral projection, and seeded Monte Carlo on mt19937_64.
Laws: 'normal' N(0, 1) and 'uniform' U[-1, 1]."""
import math
from functools import lru_cache

import numpy as np

from .errors import PeriStepError

R = np.longdouble  # x87 extended precision, as the host's long double


def _recurrence(law, k):
    """s_k of x p_k = s_{k+1} p_{k+1} + s_k p_{k-1} for the orthonormal polynomials of the law."""
    if k <= 0:
        return R(0)
    kk = R(k)
    return np.sqrt(kk) if law == "normal" else kk / np.sqrt(4 * kk * kk - 1)


def _polynomial(law, n, x):
    """p_n(x) and p_n'(x)."""
    p, p_prev, d, d_prev = R(1), R(0), R(0), R(0)
    for k in range(n):
        s, s_next = _recurrence(law, k), _recurrence(law, k + 1)
        p_next = (x * p - s * p_prev) / s_next
        d_next = (x * d + p - s * d_prev) / s_next
        p_prev, p, d_prev, d = p, p_next, d, d_next
    return p, d


def orthonormal_polynomials(law, n, x):
    """p_0(x) .. p_n(x) in long double."""
    p = [R(1)]
    for k in range(n):
        previous = _recurrence(law, k) * p[k - 1] if k > 0 else R(0)
        p.append((x * p[k] - previous) / _recurrence(law, k + 1))
    return p


@lru_cache(maxsize=None)
def gauss_rule(law, points):
    """(nodes, weights) of the n-point Gauss rule, probability weights, symmetric to the bit."""
    if points < 1:
        raise PeriStepError(f"a Gauss rule needs at least 1 point, got {points}")
    n = points
    # Starting values from numpy; Newton on p_n in long double then finds the host's roots.
    guess = (np.polynomial.hermite_e.hermegauss if law == "normal" else np.polynomial.legendre.leggauss)(n)[0]
    nodes = []
    for x in guess:
        x = R(x)
        for _ in range(3):
            p, d = _polynomial(law, n, x)
            if d == 0:
                break
            x -= p / d
        nodes.append(x)
    for i in range(n // 2):
        x = (nodes[n - 1 - i] - nodes[i]) / 2
        nodes[i], nodes[n - 1 - i] = -x, x
    if n % 2:
        nodes[n // 2] = R(0)
    weights = []
    total = R(0)
    for x in nodes:
        w = R(1) / sum_of_squares(orthonormal_polynomials(law, n - 1, x))
        weights.append(w)
        total += w
    weights = [w / total for w in weights]
    # Rounded to double keeping the symmetry exact (host: detail::toDouble).
    out_nodes, out_weights = [0.0] * n, [0.0] * n
    for i in range(n // 2, n):
        mirror = n - 1 - i
        out_nodes[i] = float(nodes[i])
        out_nodes[mirror] = -out_nodes[i]
        out_weights[i] = out_weights[mirror] = float((weights[i] + weights[mirror]) / 2)
    return tuple(out_nodes), tuple(out_weights)


def sum_of_squares(values):
    total = R(0)
    for v in values:
        total += v * v
    return total


def tensor_grid(laws, points):
    """(points [Q, N], weights [Q]): the tensor product, last coordinate fastest."""
    if points < 1:
        raise PeriStepError("the tensor rule's level is the number of points per coordinate, >= 1")
    rules = [gauss_rule(law, points) for law in laws]
    nodes, weights = [], []
    for digits in np.ndindex(*([points] * len(laws))):
        w = 1.0
        for rule, i in zip(rules, digits):
            w *= rule[1][i]
        nodes.append([rule[0][i] for rule, i in zip(rules, digits)])
        weights.append(w)
    return np.array(nodes).reshape(len(weights), len(laws)), np.array(weights)


def _indices(dims, budget):
    """Every multi-index i >= 0 with |i| <= budget, in lexicographic order."""
    if dims == 0:
        yield ()
        return
    for first in range(budget + 1):
        for rest in _indices(dims - 1, budget - first):
            yield (first, *rest)


def _tensor_nodes(laws, level):
    """The terms of the combination technique, A(L, N) of 000:(3.8): (index, coefficient, point, weight)
    for every node of every tensor rule, multi-indices in lexicographic order, last coordinate fastest;
    the weight (long double) is the tensor rule's own."""
    dims = len(laws)
    for index in _indices(dims, level):
        gap = level - sum(index)
        if sum(index) < level - dims + 1:
            continue
        coefficient = (1.0 if gap % 2 == 0 else -1.0) * _binomial(dims - 1, gap)
        rules = [gauss_rule(law, 2 * l + 1) for law, l in zip(laws, index)]
        for digits in np.ndindex(*(len(r[0]) for r in rules)):
            w = R(1)
            for rule, i in zip(rules, digits):
                w *= R(rule[1][i])
            yield index, coefficient, tuple(rule[0][i] for rule, i in zip(rules, digits)), w


def _binomial(n, k):
    c = 1.0
    for j in range(1, k + 1):
        c = c * (n - k + j) / j
    return c


def smolyak_grid(laws, level):
    """(points, weights) of the Smolyak grid with Gauss rules: coincident nodes merged in order of first
    appearance, their weights summed in long double."""
    if level < 0:
        raise PeriStepError(f"the Smolyak level must be >= 0, got {level}")
    if not laws:
        return np.zeros((1, 0)), np.array([1.0])
    slot, points, weights = {}, [], []
    for _, coefficient, point, w in _tensor_nodes(laws, level):
        if point not in slot:
            slot[point] = len(points)
            points.append(point)
            weights.append(R(coefficient) * w)
        else:
            weights[slot[point]] += R(coefficient) * w
    return np.array(points), np.array([float(w) for w in weights])


def sparse_projection(laws, level):
    """The sparse pseudo-spectral projection on the Smolyak grid's samples (Constantine, Eldred, Phipps
    2012): (number of coefficients, [(coefficient, sample, factor)] sorted), coefficient 0 the mean."""
    if not laws:
        return 1, [(0, 0, 1.0)]
    slot, coefficient, factor = {}, {(0,) * len(laws): 0}, {}
    for index, combination, point, w in _tensor_nodes(laws, level):
        sample = slot.setdefault(point, len(slot))
        highest = [2 * l for l in index]  # degree 4l + 1 of the (2l + 1)-point rule, halved
        p = [orthonormal_polynomials(law, h, R(x)) for law, h, x in zip(laws, highest, point)]
        for alpha in np.ndindex(*(h + 1 for h in highest)):
            psi = R(combination) * w
            for d, a in enumerate(alpha):
                psi *= p[d][a]
            c = coefficient.setdefault(tuple(alpha), len(coefficient))
            factor[(c, sample)] = factor.get((c, sample), R(0)) + psi
    return len(coefficient), [(c, s, float(f)) for (c, s), f in sorted(factor.items())]


class _MersenneTwister64:
    """std::mt19937_64, whose output the C++ standard fixes."""

    def __init__(self, seed):
        mask = (1 << 64) - 1
        self.state = [seed & mask]
        for i in range(1, 312):
            previous = self.state[-1]
            self.state.append((6364136223846793005 * (previous ^ (previous >> 62)) + i) & mask)
        self.index = 312

    def __call__(self):
        mask = (1 << 64) - 1
        if self.index >= 312:
            mt = self.state
            for i in range(312):
                x = (mt[i] & 0xFFFFFFFF80000000) | (mt[(i + 1) % 312] & 0x7FFFFFFF)
                mt[i] = mt[(i + 156) % 312] ^ (x >> 1) ^ (0xB5026F5AA96619E9 if x & 1 else 0)
            self.index = 0
        y = self.state[self.index]
        self.index += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        y ^= y >> 43
        return y & mask


def monte_carlo(laws, count, seed):
    """(points, weights 1/count): one generator read point by point, coordinate by coordinate; uniform
    2u - 1, normal by Box-Muller (cos, then sin for the next normal coordinate), u = (r >> 11) 2^-53."""
    engine = _MersenneTwister64(seed)

    def unit():
        return (engine() >> 11) * 2.0 ** -53

    spare = None
    points = []
    for _ in range(count):
        point = []
        for law in laws:
            if law == "uniform":
                point.append(2 * unit() - 1)
            elif spare is not None:
                point.append(spare)
                spare = None
            else:
                radius = math.sqrt(-2 * math.log(1 - unit()))
                angle = 2 * math.pi * unit()
                spare = radius * math.sin(angle)
                point.append(radius * math.cos(angle))
        points.append(point)
    return np.array(points).reshape(count, len(laws)), np.full(count, 1.0 / count if count else 0.0)
