#include "linalg/multifrontal_lu.hpp"

#include <algorithm>
#include <cblas.h>
#include <cmath>
#include <cstring>
#include <limits>
#include <omp.h>
#include <string>

#include "core/errors.hpp"
#include "core/memory.hpp"


namespace peristep {
namespace {

using Index = std::int32_t;

// Symmetric adjacency of A's pattern under a relabelling (no diagonal, no repeats).
struct Graph {
  std::vector<std::int64_t> start;
  std::vector<Index> adj;
  std::span<const Index> of(std::int64_t v) const {
    return {adj.data() + start[static_cast<std::size_t>(v)],
            static_cast<std::size_t>(start[static_cast<std::size_t>(v) + 1] - start[static_cast<std::size_t>(v)])};
  }
};

Graph symmetricGraph(const CsrMatrix& A, const std::vector<Index>& label) {
  const auto n = static_cast<std::size_t>(A.rows);
  Graph g;
  g.start.assign(n + 1, 0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) {
      const auto c = static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)]);
      if (c == r) continue;
      ++g.start[static_cast<std::size_t>(label[r]) + 1];
      ++g.start[static_cast<std::size_t>(label[c]) + 1];
    }
  for (std::size_t v = 0; v < n; ++v) g.start[v + 1] += g.start[v];
  g.adj.resize(static_cast<std::size_t>(g.start[n]));
  std::vector<std::int64_t> cursor(g.start.begin(), g.start.end() - 1);
  for (std::size_t r = 0; r < n; ++r)
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) {
      const auto c = static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)]);
      if (c == r) continue;
      g.adj[static_cast<std::size_t>(cursor[static_cast<std::size_t>(label[r])]++)] = label[c];
      g.adj[static_cast<std::size_t>(cursor[static_cast<std::size_t>(label[c])]++)] = label[r];
    }
  // Drop repeats (a symmetric pattern lists every pair twice), compacting in place.
  std::vector<std::int64_t> seen(n, -1);
  std::int64_t out = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const std::int64_t begin = g.start[v], end = g.start[v + 1];
    g.start[v] = out;
    for (std::int64_t k = begin; k < end; ++k) {
      const Index u = g.adj[static_cast<std::size_t>(k)];
      if (seen[static_cast<std::size_t>(u)] == static_cast<std::int64_t>(v)) continue;
      seen[static_cast<std::size_t>(u)] = static_cast<std::int64_t>(v);
      g.adj[static_cast<std::size_t>(out++)] = u;
    }
  }
  g.start[n] = out;
  g.adj.resize(static_cast<std::size_t>(out));
  g.adj.shrink_to_fit();
  return g;
}

// The graph of positions as a graph of internal indices (unknown u has position[u] and internal[u]).
Graph relabelled(const Graph& g, const std::vector<Index>& position, const std::vector<Index>& internal) {
  const std::size_t n = position.size();
  std::vector<Index> toInternal(n);
  for (std::size_t u = 0; u < n; ++u) toInternal[static_cast<std::size_t>(position[u])] = internal[u];
  std::vector<Index> fromInternal(n);
  for (std::size_t q = 0; q < n; ++q) fromInternal[static_cast<std::size_t>(toInternal[q])] = static_cast<Index>(q);
  Graph h;
  h.start.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) h.start[v + 1] = h.start[v] + static_cast<std::int64_t>(g.of(fromInternal[v]).size());
  h.adj.resize(g.adj.size());
#pragma omp parallel for schedule(static)
  for (std::size_t v = 0; v < n; ++v) {
    Index* out = h.adj.data() + h.start[v];
    for (Index q : g.of(fromInternal[v])) *out++ = toInternal[static_cast<std::size_t>(q)];
  }
  return h;
}

// C -= A B (A m x k, B k x n, column-major): BLAS for large products, plain loops for the many small ones
// at the leaves of the tree, where a BLAS call costs more than its flops.
void subtractProduct(int m, int n, int k, const float* a, int lda, const float* b, int ldb, float* c, int ldc) {
  if (m == 0 || n == 0 || k == 0) return;
  if (static_cast<std::int64_t>(m) * n * k > 32768) {
    cblas_sgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, m, n, k, -1.0f, a, lda, b, ldb, 1.0f, c, ldc);
    return;
  }
  for (int j = 0; j < n; ++j) {
    float* cj = c + static_cast<std::ptrdiff_t>(j) * ldc;
    for (int l = 0; l < k; ++l) {
      const float f = b[l + static_cast<std::ptrdiff_t>(j) * ldb];
      const float* al = a + static_cast<std::ptrdiff_t>(l) * lda;
      for (int i = 0; i < m; ++i) cj[i] -= al[i] * f;
    }
  }
}

// B := L^-1 B, L unit lower triangular (m x m), B m x n.
void solveUnitLower(int m, int n, const float* l, int ldl, float* b, int ldb) {
  if (m == 0 || n == 0) return;
  if (static_cast<std::int64_t>(m) * m * n > 32768) {
    cblas_strsm(CblasColMajor, CblasLeft, CblasLower, CblasNoTrans, CblasUnit, m, n, 1.0f, l, ldl, b, ldb);
    return;
  }
  for (int j = 0; j < n; ++j) {
    float* bj = b + static_cast<std::ptrdiff_t>(j) * ldb;
    for (int c = 0; c < m; ++c) {
      const float f = bj[c];
      const float* lc = l + static_cast<std::ptrdiff_t>(c) * ldl;
      for (int i = c + 1; i < m; ++i) bj[i] -= lc[i] * f;
    }
  }
}

// B := B U^-1, U upper triangular (n x n, its diagonal not unit), B m x n.
void solveUpperRight(int m, int n, const float* u, int ldu, float* b, int ldb) {
  if (m == 0 || n == 0) return;
  if (static_cast<std::int64_t>(m) * n * n > 32768) {
    cblas_strsm(CblasColMajor, CblasRight, CblasUpper, CblasNoTrans, CblasNonUnit, m, n, 1.0f, u, ldu, b, ldb);
    return;
  }
  for (int j = 0; j < n; ++j) {
    float* bj = b + static_cast<std::ptrdiff_t>(j) * ldb;
    for (int c = 0; c < j; ++c) {
      const float f = u[c + static_cast<std::ptrdiff_t>(j) * ldu];
      const float* bc = b + static_cast<std::ptrdiff_t>(c) * ldb;
      for (int i = 0; i < m; ++i) bj[i] -= bc[i] * f;
    }
    const float inverse = 1.0f / u[j + static_cast<std::ptrdiff_t>(j) * ldu];
    for (int i = 0; i < m; ++i) bj[i] *= inverse;
  }
}

// LU without pivoting of the first p columns of the m x m front F (column-major): L and U of the pivot
// block, L21 below it, U12 beside it, and the contribution block F22 - L21 U12 in place.
void factorFront(float* F, int m, int p) {
  constexpr int kBlock = 64;
  for (int k0 = 0; k0 < p; k0 += kBlock) {
    const int b = std::min(kBlock, p - k0);
    float* diagonal = F + k0 + static_cast<std::ptrdiff_t>(k0) * m;
    for (int j = 0; j < b; ++j) {  // the b x b diagonal block, unblocked
      float* cj = diagonal + static_cast<std::ptrdiff_t>(j) * m;
      const float pivot = cj[j];
      if (!(std::isfinite(pivot) && pivot != 0.0f))
        throw SolverFailure("multifrontal LU: pivot " + std::to_string(pivot) + " (singular or unstable without pivoting)");
      const float inverse = 1.0f / pivot;
      for (int i = j + 1; i < b; ++i) cj[i] *= inverse;
      for (int jj = j + 1; jj < b; ++jj) {
        float* cjj = diagonal + static_cast<std::ptrdiff_t>(jj) * m;
        const float f = cjj[j];
        for (int i = j + 1; i < b; ++i) cjj[i] -= cj[i] * f;
      }
    }
    solveUpperRight(m - (k0 + b), b, diagonal, m, diagonal + b, m);  // L below the block
    const int rest = p - (k0 + b);
    if (rest == 0) break;
    float* u = diagonal + static_cast<std::ptrdiff_t>(b) * m;
    solveUnitLower(b, rest, diagonal, m, u, m);
    subtractProduct(m - (k0 + b), rest, b, diagonal + b, m, u, m, u + b, m);
  }
  const int r = m - p;
  if (r == 0) return;
  float* u12 = F + static_cast<std::ptrdiff_t>(p) * m;
  solveUnitLower(p, r, F, m, u12, m);
  subtractProduct(r, r, p, F + p, m, u12, m, u12 + p, m);
}

// t -= A v for A's `count` columns of length `length` (column stride ld), four columns at a time: the
// substitutions read each factor entry once, so this loop is what their speed is made of.
#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
PERISTEP_CLONES void subtractColumns(float* __restrict t, const float* __restrict a, std::ptrdiff_t ld,
                                     const float* __restrict v, int count, int length) {
  int j = 0;
  for (; j + 4 <= count; j += 4) {
    const float* a0 = a + j * ld;
    const float* a1 = a0 + ld;
    const float* a2 = a1 + ld;
    const float* a3 = a2 + ld;
    const float v0 = v[j], v1 = v[j + 1], v2 = v[j + 2], v3 = v[j + 3];
    for (int i = 0; i < length; ++i) t[i] -= a0[i] * v0 + a1[i] * v1 + a2[i] * v2 + a3[i] * v3;
  }
  for (; j < count; ++j) {
    const float* a0 = a + j * ld;
    const float v0 = v[j];
    for (int i = 0; i < length; ++i) t[i] -= a0[i] * v0;
  }
}

// Elimination tree of the first nF unknowns of g in their order (Liu's algorithm with path compression).
std::vector<Index> eliminationTree(const Graph& g, std::size_t nF) {
  std::vector<Index> parent(nF, -1), ancestor(nF, -1);
  for (std::size_t i = 0; i < nF; ++i)
    for (Index k : g.of(static_cast<std::int64_t>(i)))
      for (Index next; k != -1 && static_cast<std::size_t>(k) < i; k = next) {
        next = ancestor[static_cast<std::size_t>(k)];
        ancestor[static_cast<std::size_t>(k)] = static_cast<Index>(i);
        if (next == -1) parent[static_cast<std::size_t>(k)] = static_cast<Index>(i);
      }
  return parent;
}

// Rank of each node in a postorder of the forest (children in their given order), so that every subtree
// is a contiguous range.
std::vector<Index> postorderRanks(const std::vector<Index>& treeParent) {
  const std::size_t nF = treeParent.size();
  std::vector<Index> childHead(nF, -1), nextSibling(nF, -1), postRank(nF);
  for (std::size_t j = nF; j-- > 0;)
    if (treeParent[j] != -1) {
      nextSibling[j] = childHead[static_cast<std::size_t>(treeParent[j])];
      childHead[static_cast<std::size_t>(treeParent[j])] = static_cast<Index>(j);
    }
  Index next = 0;
  std::vector<Index> stack;
  for (std::size_t root = 0; root < nF; ++root) {
    if (treeParent[root] != -1) continue;
    stack.push_back(static_cast<Index>(root));
    while (!stack.empty()) {
      const Index v = stack.back();
      const Index c = childHead[static_cast<std::size_t>(v)];
      if (c != -1) {
        childHead[static_cast<std::size_t>(v)] = nextSibling[static_cast<std::size_t>(c)];
        stack.push_back(c);
      } else {
        postRank[static_cast<std::size_t>(v)] = next++;
        stack.pop_back();
      }
    }
  }
  return postRank;
}

// Column counts of L (rows below the diagonal, Z rows included) for the postordered tree `parent` of the
// first nF of n unknowns: Gilbert, Ng and Peyton's skeleton algorithm (as in CSparse's cs_counts) in
// O(|A|), where walking each row's subtree cost O(|L|): 0.38 s per zone at h = 2 um. A virtual root nF
// above the forest's roots tops the row subtrees of the Z rows, which in the F forest end at its roots.
std::vector<std::int64_t> columnCounts(const Graph& g, const std::vector<Index>& parent, std::size_t n) {
  const std::size_t nF = parent.size(), root = nF;
  // link: union-find towards the lowest common ancestor of two leaves of a row subtree.
  std::vector<Index> up(nF + 1, -1), first(nF + 1, -1), link(nF + 1), maxFirst(n, -1), prevLeaf(n, -1);
  std::vector<std::int64_t> delta(nF + 1, 0);
  for (std::size_t j = 0; j < nF; ++j) up[j] = parent[j] == -1 ? static_cast<Index>(root) : parent[j];
  for (std::size_t k = 0; k <= nF; ++k) {
    delta[k] = first[k] == -1 ? 1 : 0;  // an etree leaf: its row has only the diagonal
    for (Index j = static_cast<Index>(k); j != -1 && first[static_cast<std::size_t>(j)] == -1; j = up[static_cast<std::size_t>(j)])
      first[static_cast<std::size_t>(j)] = static_cast<Index>(k);
    link[k] = static_cast<Index>(k);
  }
  for (std::size_t j = 0; j < nF; ++j) {
    --delta[static_cast<std::size_t>(up[j])];
    for (Index i : g.of(static_cast<std::int64_t>(j))) {
      const auto row = static_cast<std::size_t>(i);
      // Is j a leaf of row i's subtree (no column of it in j's subtree seen yet)?
      if (row <= j || first[j] <= maxFirst[row]) continue;
      maxFirst[row] = first[j];
      const Index previous = prevLeaf[row];
      prevLeaf[row] = static_cast<Index>(j);
      ++delta[j];
      if (previous == -1) continue;
      // Overlap with the path from the previous leaf: subtract at their lowest common ancestor.
      Index q = previous;
      while (q != link[static_cast<std::size_t>(q)]) q = link[static_cast<std::size_t>(q)];
      for (Index s = previous; s != q;) {
        const Index next = link[static_cast<std::size_t>(s)];
        link[static_cast<std::size_t>(s)] = q;
        s = next;
      }
      --delta[static_cast<std::size_t>(q)];
    }
    link[j] = up[j];
  }
  for (std::size_t j = 0; j < nF; ++j) delta[static_cast<std::size_t>(up[j])] += delta[j];
  std::vector<std::int64_t> count(nF);
  for (std::size_t j = 0; j < nF; ++j) count[j] = delta[j] - 1;
  return count;
}

// Entries of a supernode of p columns and m rows (the square block and the rectangle below it).
std::int64_t frontStorage(std::int64_t p, std::int64_t m) { return p * (2 * m - p); }

// Supernodes as ranges of columns: fundamental supernodes (chains j -> j + 1 where j is the only child and
// the structure just shrinks by one), then relaxed amalgamation (CHOLMOD's rule): a supernode absorbs the
// child just before it while the explicit zeros this adds stay small against its size; larger fronts make
// the dense kernels efficient. Returns the first column of each supernode and nF.
std::vector<Index> amalgamatedSupernodes(const std::vector<Index>& parent, const std::vector<std::int64_t>& count) {
  const std::size_t nF = parent.size();
  std::vector<Index> childCount(nF, 0);
  for (std::size_t j = 0; j < nF; ++j)
    if (parent[j] != -1) ++childCount[static_cast<std::size_t>(parent[j])];
  std::vector<Index> fundFirst, fundOf(nF);
  for (std::size_t j = 0; j < nF; ++j) {
    const bool extends = j > 0 && parent[j - 1] == static_cast<Index>(j) && childCount[j] == 1 && count[j - 1] == count[j] + 1;
    if (!extends) fundFirst.push_back(static_cast<Index>(j));
    fundOf[j] = static_cast<Index>(fundFirst.size() - 1);
  }
  fundFirst.push_back(static_cast<Index>(nF));
  struct Node {
    Index firstFund, lastFund;
    std::int64_t cols, rows, zeros;
  };
  std::vector<Node> nodes;
  for (std::size_t f = 0; f + 1 < fundFirst.size(); ++f) {
    const std::int64_t p = fundFirst[f + 1] - fundFirst[f];
    Node P{static_cast<Index>(f), static_cast<Index>(f), p, p + count[static_cast<std::size_t>(fundFirst[f + 1] - 1)], 0};
    while (!nodes.empty()) {
      const Node& C = nodes.back();
      const Index lastColumn = fundFirst[static_cast<std::size_t>(C.lastFund) + 1] - 1;
      const Index up = parent[static_cast<std::size_t>(lastColumn)];
      if (up == -1 || fundOf[static_cast<std::size_t>(up)] < P.firstFund || fundOf[static_cast<std::size_t>(up)] > P.lastFund) break;
      const std::int64_t cols = C.cols + P.cols, rows = C.cols + P.rows, total = frontStorage(cols, rows);
      const std::int64_t zeros = C.zeros + P.zeros + total - frontStorage(C.cols, C.rows) - frontStorage(P.cols, P.rows);
      const double share = static_cast<double>(zeros) / static_cast<double>(total);
      if (!(cols <= 4 || (cols <= 16 && share < 0.8) || (cols <= 48 && share < 0.1) || share < 0.05)) break;
      P = Node{C.firstFund, P.lastFund, cols, rows, zeros};
      nodes.pop_back();
    }
    nodes.push_back(P);
  }
  std::vector<Index> first(nodes.size() + 1);
  for (std::size_t s = 0; s < nodes.size(); ++s) first[s] = fundFirst[static_cast<std::size_t>(nodes[s].firstFund)];
  first[nodes.size()] = static_cast<Index>(nF);
  return first;
}

// Row lists: a supernode's columns, then the union of its columns' pattern and its children's rows below it.
void rowLists(const Graph& g, std::size_t n, const std::vector<Index>& first, const std::vector<Index>& childStart,
              const std::vector<Index>& children, std::vector<std::int64_t>& rowStart, std::vector<Index>& rows) {
  const std::size_t ns = first.size() - 1;
  rowStart.assign(ns + 1, 0);
  rows.clear();
  std::vector<Index> mark(n, -1), below;
  for (std::size_t s = 0; s < ns; ++s) {
    const Index f = first[s], l = first[s + 1] - 1;
    for (Index j = f; j <= l; ++j) {
      rows.push_back(j);
      mark[static_cast<std::size_t>(j)] = static_cast<Index>(s);
    }
    below.clear();
    auto take = [&](Index i) {
      if (i > l && mark[static_cast<std::size_t>(i)] != static_cast<Index>(s)) {
        mark[static_cast<std::size_t>(i)] = static_cast<Index>(s);
        below.push_back(i);
      }
    };
    for (Index j = f; j <= l; ++j)
      for (Index i : g.of(j)) take(i);
    for (Index k = childStart[s]; k < childStart[s + 1]; ++k) {
      const auto c = static_cast<std::size_t>(children[static_cast<std::size_t>(k)]);
      for (std::int64_t t = rowStart[c] + (first[c + 1] - first[c]); t < rowStart[c + 1]; ++t)
        take(rows[static_cast<std::size_t>(t)]);
    }
    std::sort(below.begin(), below.end());
    rows.insert(rows.end(), below.begin(), below.end());
    rowStart[s + 1] = static_cast<std::int64_t>(rows.size());
  }
}

}  // namespace

void MultifrontalLu::analyze(const CsrMatrix& A, const std::vector<std::int32_t>& position, std::size_t schurCount,
                             const std::vector<std::int64_t>& schurUnknowns) {
  require(A.rows == A.cols && static_cast<std::int64_t>(position.size()) == A.rows,
          "multifrontal LU: square matrix and one position per unknown");
  require(A.nonZeros() < std::numeric_limits<Index>::max(), "multifrontal LU: too many entries");
  require(schurUnknowns.size() == schurCount, "multifrontal LU: Schur list and count differ");
  // The last factors are of no use after a new analysis: free them before its arrays come on top.
  freeStorage(factors_);
  n_ = A.rows;
  z_ = static_cast<std::int64_t>(schurCount);
  nF_ = n_ - z_;
  const auto nF = static_cast<std::size_t>(nF_);

  Graph g = symmetricGraph(A, position);
  const std::vector<Index> parent = labelInPostorder(eliminationTree(g, nF), position, schurUnknowns);
  g = relabelled(g, position, internal_);
  const std::vector<Index> nodeOfColumn = setSupernodes(parent, columnCounts(g, parent, static_cast<std::size_t>(n_)));
  rowLists(g, static_cast<std::size_t>(n_), first_, childStart_, children_, rowStart_, rows_);
  g = {};
  placeEntries(A, nodeOfColumn);
  measureFronts();
  splitForSubstitutions();
}

// internal_: the F unknowns in the postorder of their elimination tree, the Schur unknowns after them in
// their given order. Returns the tree in the new labels.
std::vector<MultifrontalLu::Index> MultifrontalLu::labelInPostorder(const std::vector<Index>& treeParent,
                                                                   const std::vector<std::int32_t>& position,
                                                                   const std::vector<std::int64_t>& schurUnknowns) {
  const std::size_t n = static_cast<std::size_t>(n_), nF = treeParent.size();
  const std::vector<Index> postRank = postorderRanks(treeParent);
  internal_.assign(n, -1);
  for (std::size_t u = 0; u < n; ++u)
    if (static_cast<std::size_t>(position[u]) < nF) internal_[u] = postRank[static_cast<std::size_t>(position[u])];
  for (std::size_t t = 0; t < schurUnknowns.size(); ++t) {
    const auto u = static_cast<std::size_t>(schurUnknowns[t]);
    require(static_cast<std::size_t>(position[u]) >= nF, "multifrontal LU: the Schur unknowns must come last");
    internal_[u] = static_cast<Index>(nF + t);
  }
  std::vector<Index> parent(nF, -1);
  for (std::size_t j = 0; j < nF; ++j)
    if (treeParent[j] != -1)
      parent[static_cast<std::size_t>(postRank[j])] = postRank[static_cast<std::size_t>(treeParent[j])];
  return parent;
}

// first_, parent_ and the children lists of the supernodes; returns the supernode of each column.
std::vector<MultifrontalLu::Index> MultifrontalLu::setSupernodes(const std::vector<Index>& parent,
                                                                const std::vector<std::int64_t>& count) {
  const std::size_t nF = parent.size();
  first_ = amalgamatedSupernodes(parent, count);
  const std::size_t ns = first_.size() - 1;
  std::vector<Index> nodeOfColumn(nF);
  for (std::size_t s = 0; s < ns; ++s)
    std::fill(nodeOfColumn.begin() + first_[s], nodeOfColumn.begin() + first_[s + 1], static_cast<Index>(s));
  parent_.assign(ns, -1);
  for (std::size_t s = 0; s < ns; ++s) {
    const Index up = parent[static_cast<std::size_t>(first_[s + 1] - 1)];
    if (up != -1) parent_[s] = nodeOfColumn[static_cast<std::size_t>(up)];
  }
  childStart_.assign(ns + 1, 0);
  for (std::size_t s = 0; s < ns; ++s)
    if (parent_[s] != -1) ++childStart_[static_cast<std::size_t>(parent_[s]) + 1];
  for (std::size_t s = 0; s < ns; ++s) childStart_[s + 1] += childStart_[s];
  children_.resize(static_cast<std::size_t>(childStart_[ns]));
  std::vector<Index> cursor(childStart_.begin(), childStart_.end() - 1);
  for (std::size_t s = 0; s < ns; ++s)
    if (parent_[s] != -1) children_[static_cast<std::size_t>(cursor[static_cast<std::size_t>(parent_[s])]++)] = static_cast<Index>(s);
  return nodeOfColumn;
}

// Where each of A's entries goes: the front of the supernode holding the smaller of its two indices, or S.
void MultifrontalLu::placeEntries(const CsrMatrix& A, const std::vector<Index>& nodeOfColumn) {
  const std::size_t n = static_cast<std::size_t>(n_), nF = static_cast<std::size_t>(nF_), ns = first_.size() - 1;
  auto localIndex = [&](std::size_t s, Index i) -> std::int64_t {
    if (i < first_[s + 1]) return i - first_[s];
    const std::int64_t p = first_[s + 1] - first_[s];
    const Index* begin = rows_.data() + rowStart_[s] + p;
    const Index* end = rows_.data() + rowStart_[s + 1];
    return p + (std::lower_bound(begin, end, i) - begin);
  };
  const auto nnz = static_cast<std::size_t>(A.nonZeros());
  std::vector<Index> owner(nnz);
  std::vector<std::int32_t> offset(nnz);
  for (std::size_t s = 0; s < ns; ++s)
    require(rowStart_[s + 1] - rowStart_[s] < 46341, "multifrontal LU: front too large");  // m^2 in 32 bits
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::int64_t r = 0; r < n_; ++r)
    for (std::int64_t k = A.rowStart[static_cast<std::size_t>(r)]; k < A.rowStart[static_cast<std::size_t>(r) + 1]; ++k) {
      const Index i = internal_[static_cast<std::size_t>(r)], j = internal_[static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)])];
      const auto e = static_cast<std::size_t>(k);
      if (static_cast<std::size_t>(std::min(i, j)) >= nF) {
        owner[e] = -1;
        continue;
      }
      const auto s = static_cast<std::size_t>(nodeOfColumn[static_cast<std::size_t>(std::min(i, j))]);
      const std::int64_t m = rowStart_[s + 1] - rowStart_[s];
      owner[e] = static_cast<Index>(s);
      offset[e] = static_cast<std::int32_t>(localIndex(s, i) + localIndex(s, j) * m);
    }
  ownStart_.assign(ns + 1, 0);
  schurEntry_.clear();
  schurOffset_.clear();
  for (std::size_t r = 0; r < n; ++r)
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) {
      const Index s = owner[static_cast<std::size_t>(k)];
      if (s != -1) {
        ++ownStart_[static_cast<std::size_t>(s) + 1];
        continue;
      }
      const Index i = internal_[r], j = internal_[static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)])];
      schurEntry_.push_back(k);
      schurOffset_.push_back(static_cast<std::int64_t>(i - nF_) + static_cast<std::int64_t>(j - nF_) * z_);
    }
  for (std::size_t s = 0; s < ns; ++s) ownStart_[s + 1] += ownStart_[s];
  ownEntry_.resize(static_cast<std::size_t>(ownStart_[ns]));
  ownOffset_.resize(ownEntry_.size());
  std::vector<std::int64_t> cursor(ownStart_.begin(), ownStart_.end() - 1);
  for (std::size_t e = 0; e < nnz; ++e)
    if (owner[e] != -1) {
      const auto at = static_cast<std::size_t>(cursor[static_cast<std::size_t>(owner[e])]++);
      ownEntry_[at] = static_cast<Index>(e);
      ownOffset_[at] = offset[e];
    }
}

// Sizes: the factors, the largest front, and the peak of the stack of contribution blocks (postorder).
void MultifrontalLu::measureFronts() {
  const std::size_t ns = first_.size() - 1;
  factorStart_.assign(ns + 1, 0);
  maxFront_ = 0;
  stackPeak_ = 0;
  std::int64_t stackTop = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    const std::int64_t p = first_[s + 1] - first_[s], m = rowStart_[s + 1] - rowStart_[s], r = m - p;
    factorStart_[s + 1] = factorStart_[s] + frontStorage(p, m);
    maxFront_ = std::max(maxFront_, m * m);
    for (Index k = childStart_[s]; k < childStart_[s + 1]; ++k) {
      const auto c = static_cast<std::size_t>(children_[static_cast<std::size_t>(k)]);
      const std::int64_t rc = (rowStart_[c + 1] - rowStart_[c]) - (first_[c + 1] - first_[c]);
      stackTop -= rc * rc;
    }
    stackTop += r * r;
    stackPeak_ = std::max(stackPeak_, stackTop);
  }
  factorEntries_ = factorStart_[ns];
}

// Two groups of whole subtrees of about equal factor size, one per core in the substitutions, and the
// supernodes above them, done after (forward) or before (backward) both groups. The split opens the
// heaviest subtree until the groups balance to 5%.
void MultifrontalLu::splitForSubstitutions() {
  const std::size_t ns = first_.size() - 1;
  std::vector<std::int64_t> weight(ns), size(ns, 1);
  for (std::size_t s = 0; s < ns; ++s) weight[s] = factorStart_[s + 1] - factorStart_[s];
  for (std::size_t s = 0; s < ns; ++s)
    if (parent_[s] != -1) {
      weight[static_cast<std::size_t>(parent_[s])] += weight[s];
      size[static_cast<std::size_t>(parent_[s])] += size[s];
    }
  std::vector<Index> open;
  for (std::size_t s = 0; s < ns; ++s)
    if (parent_[s] == -1) open.push_back(static_cast<Index>(s));
  std::size_t cut = 0;
  for (int step = 0; step < 256 && !open.empty(); ++step) {
    std::int64_t total = 0, prefix = 0, best = -1;
    for (Index s : open) total += weight[static_cast<std::size_t>(s)];
    for (std::size_t k = 0; k <= open.size(); ++k) {
      const std::int64_t gap = std::abs(2 * prefix - total);
      if (best < 0 || gap < best) {
        best = gap;
        cut = k;
      }
      if (k < open.size()) prefix += weight[static_cast<std::size_t>(open[k])];
    }
    if (best * 20 <= total) break;
    const auto heaviest = static_cast<std::size_t>(
        std::max_element(open.begin(), open.end(), [&](Index a, Index b) { return weight[static_cast<std::size_t>(a)] < weight[static_cast<std::size_t>(b)]; }) -
        open.begin());
    const Index s = open[heaviest];
    if (childStart_[static_cast<std::size_t>(s)] == childStart_[static_cast<std::size_t>(s) + 1]) break;
    open.erase(open.begin() + static_cast<std::ptrdiff_t>(heaviest));
    open.insert(open.begin() + static_cast<std::ptrdiff_t>(heaviest), children_.begin() + childStart_[static_cast<std::size_t>(s)],
                children_.begin() + childStart_[static_cast<std::size_t>(s) + 1]);
  }
  owner_.assign(static_cast<std::size_t>(n_), -1);
  std::vector<std::int8_t> nodeGroup(ns, -1);
  for (std::size_t k = 0; k < open.size(); ++k) {
    const auto root = static_cast<std::size_t>(open[k]);
    for (std::size_t s = root + 1 - static_cast<std::size_t>(size[root]); s <= root; ++s) nodeGroup[s] = k < cut ? 0 : 1;
  }
  for (auto& group : group_) group.clear();
  above_.clear();
  for (std::size_t s = 0; s < ns; ++s) {
    if (nodeGroup[s] < 0) {
      above_.push_back(static_cast<Index>(s));
      continue;
    }
    group_[static_cast<std::size_t>(nodeGroup[s])].push_back(static_cast<Index>(s));
    std::fill(owner_.begin() + first_[s], owner_.begin() + first_[s + 1], nodeGroup[s]);
  }
}

void MultifrontalLu::factorize(const CsrMatrix& A, std::span<const double> scale, std::vector<double>& schur) {
  require(analyzed() && A.rows == n_ && static_cast<std::int64_t>(scale.size()) == n_,
          "multifrontal LU: factorize needs the analysed pattern and one scale factor per unknown");
  std::vector<float> value(static_cast<std::size_t>(A.nonZeros()));
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < n_; ++r)
    for (std::int64_t k = A.rowStart[static_cast<std::size_t>(r)]; k < A.rowStart[static_cast<std::size_t>(r) + 1]; ++k)
      value[static_cast<std::size_t>(k)] = static_cast<float>(A.value[static_cast<std::size_t>(k)] *
                                                              (scale[static_cast<std::size_t>(r)] *
                                                               scale[static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)])]));
  factors_.resize(static_cast<std::size_t>(factorEntries_));
  stack_.resize(static_cast<std::size_t>(stackPeak_));
  place_.resize(first_.size() - 1);
  std::vector<float> front(static_cast<std::size_t>(maxFront_));
  std::vector<Index> local(static_cast<std::size_t>(n_));
  std::int64_t top = 0;
  for (std::size_t s = 0; s + 1 < first_.size(); ++s) factorNode(s, value, front, local, top);
  // S = A_ZZ + the contribution blocks of the roots (all their rows are in Z).
  const auto z = static_cast<std::size_t>(z_);
  schur.assign(z * z, 0.0);
  for (std::size_t e = 0; e < schurEntry_.size(); ++e)
    schur[static_cast<std::size_t>(schurOffset_[e])] += value[static_cast<std::size_t>(schurEntry_[e])];
  for (std::size_t c = 0; c + 1 < first_.size(); ++c) {
    if (parent_[c] != -1) continue;
    const auto pc = static_cast<std::int64_t>(first_[c + 1] - first_[c]);
    const std::int64_t rc = rowStart_[c + 1] - rowStart_[c] - pc;
    const Index* idx = rows_.data() + rowStart_[c] + pc;
    const float* cb = stack_.data() + place_[c];
    for (std::int64_t jc = 0; jc < rc; ++jc)
      for (std::int64_t ic = 0; ic < rc; ++ic)
        schur[static_cast<std::size_t>(idx[ic] - nF_) + static_cast<std::size_t>(idx[jc] - nF_) * z] += cb[ic + jc * rc];
  }
  freeStorage(stack_);  // the substitutions do not need it
}

// Supernode s: its front assembled from A's entries and its children's contribution blocks, factorized, its
// factors stored and its own contribution block put on the stack (whose top is `top`).
void MultifrontalLu::factorNode(std::size_t s, const std::vector<float>& value, std::vector<float>& front,
                                std::vector<Index>& local, std::int64_t& top) {
  const int p = first_[s + 1] - first_[s];
  const auto m = static_cast<int>(rowStart_[s + 1] - rowStart_[s]);
  const int r = m - p;
  float* F = front.data();
  std::fill(F, F + static_cast<std::ptrdiff_t>(m) * m, 0.0f);
  for (std::int64_t e = ownStart_[s]; e < ownStart_[s + 1]; ++e)
    F[ownOffset_[static_cast<std::size_t>(e)]] += value[static_cast<std::size_t>(ownEntry_[static_cast<std::size_t>(e)])];
  const Index* rows = rows_.data() + rowStart_[s];
  if (childStart_[s] < childStart_[s + 1])
    for (int t = 0; t < m; ++t) local[static_cast<std::size_t>(rows[t])] = t;
  for (Index k = childStart_[s]; k < childStart_[s + 1]; ++k) {  // extend-add
    const auto c = static_cast<std::size_t>(children_[static_cast<std::size_t>(k)]);
    const auto pc = static_cast<int>(first_[c + 1] - first_[c]);
    const auto rc = static_cast<int>(rowStart_[c + 1] - rowStart_[c]) - pc;
    const Index* idx = rows_.data() + rowStart_[c] + pc;
    const float* cb = stack_.data() + place_[c];
    for (int jc = 0; jc < rc; ++jc) {
      float* column = F + static_cast<std::ptrdiff_t>(local[static_cast<std::size_t>(idx[jc])]) * m;
      const float* source = cb + static_cast<std::ptrdiff_t>(jc) * rc;
      for (int ic = 0; ic < rc; ++ic) column[local[static_cast<std::size_t>(idx[ic])]] += source[ic];
    }
    top = std::min(top, place_[c]);  // popped: the children's blocks are the stack's top
  }
  factorFront(F, m, p);
  float* out = factors_.data() + factorStart_[s];
  std::memcpy(out, F, sizeof(float) * static_cast<std::size_t>(m) * static_cast<std::size_t>(p));
  out += static_cast<std::ptrdiff_t>(m) * p;
  for (int t = 0; t < r; ++t)
    std::memcpy(out + static_cast<std::ptrdiff_t>(t) * p, F + static_cast<std::ptrdiff_t>(p + t) * m, sizeof(float) * static_cast<std::size_t>(p));
  float* cb = stack_.data() + top;
  for (int t = 0; t < r; ++t)
    std::memcpy(cb + static_cast<std::ptrdiff_t>(t) * r, F + static_cast<std::ptrdiff_t>(p + t) * m + p, sizeof(float) * static_cast<std::size_t>(r));
  place_[s] = top;
  top += static_cast<std::int64_t>(r) * r;
}

// The forward substitution of supernode s: its rows of w solved, the updates of the rows below added to w,
// or to `outside` for rows outside `group` (when `outside` is given).
void MultifrontalLu::forwardNode(std::size_t s, float* w, std::vector<float>& f, float* outside, std::int8_t group) const {
  const int p = first_[s + 1] - first_[s];
  const auto m = static_cast<int>(rowStart_[s + 1] - rowStart_[s]);
  const float* L = factors_.data() + factorStart_[s];
  // The front's rows in one vector: y (this supernode's unknowns), then the updates of the rows below.
  f.assign(static_cast<std::size_t>(m), 0.0f);
  std::copy(w + first_[s], w + first_[s] + p, f.begin());
  for (int j0 = 0; j0 < p; j0 += 4) {
    const int b = std::min(4, p - j0);
    for (int j = j0; j < j0 + b; ++j)  // the unit lower triangle of the block's diagonal
      for (int i = j + 1; i < j0 + b; ++i)
        f[static_cast<std::size_t>(i)] -= L[i + static_cast<std::ptrdiff_t>(j) * m] * f[static_cast<std::size_t>(j)];
    subtractColumns(f.data() + j0 + b, L + j0 + b + static_cast<std::ptrdiff_t>(j0) * m, m, f.data() + j0, b, m - j0 - b);
  }
  std::copy(f.begin(), f.begin() + p, w + first_[s]);
  const Index* idx = rows_.data() + rowStart_[s] + p;
  for (int i = 0; i < m - p; ++i) {
    const auto row = static_cast<std::size_t>(idx[i]);
    (outside && owner_[row] != group ? outside : w)[row] += f[static_cast<std::size_t>(p + i)];
  }
}

// The backward substitution of supernode s, the rows below it already solved.
void MultifrontalLu::backwardNode(std::size_t s, float* w, std::vector<float>& xb) const {
  const int p = first_[s + 1] - first_[s];
  const auto m = static_cast<int>(rowStart_[s + 1] - rowStart_[s]);
  const int r = m - p;
  const float* L = factors_.data() + factorStart_[s];  // U11 is its upper triangle
  float* y = w + first_[s];
  const Index* idx = rows_.data() + rowStart_[s] + p;
  xb.resize(static_cast<std::size_t>(r));
  for (int t = 0; t < r; ++t) xb[static_cast<std::size_t>(t)] = w[idx[t]];
  subtractColumns(y, L + static_cast<std::ptrdiff_t>(m) * p, p, xb.data(), r, p);  // y -= U12 x_below
  for (int j0 = (p - 1) / 4 * 4; j0 >= 0; j0 -= 4) {
    const int b = std::min(4, p - j0);
    for (int j = j0 + b; j-- > j0;) {  // the upper triangle of the block's diagonal
      y[j] /= L[j + static_cast<std::ptrdiff_t>(j) * m];
      for (int i = j0; i < j; ++i) y[i] -= L[i + static_cast<std::ptrdiff_t>(j) * m] * y[j];
    }
    subtractColumns(y, L + static_cast<std::ptrdiff_t>(j0) * m, m, y + j0, b, j0);
  }
}

// Both groups at once, each adding its updates of the rows above it into its own vector; the sums enter w
// in a fixed order, so the result does not depend on the number of threads.
void MultifrontalLu::forward() {
  float* w = work_.data();
  const auto n = static_cast<std::size_t>(n_);
  outside_.assign(2 * n, 0.0f);
#pragma omp parallel
  {
    std::vector<float> f;
    for (int g = omp_get_thread_num(); g < 2; g += omp_get_num_threads())
      for (Index s : group_[static_cast<std::size_t>(g)])
        forwardNode(static_cast<std::size_t>(s), w, f, outside_.data() + static_cast<std::size_t>(g) * n, static_cast<std::int8_t>(g));
  }
  for (std::size_t i = 0; i < n; ++i)
    if (owner_[i] < 0) w[i] += outside_[i] + outside_[n + i];
  std::vector<float> f;
  for (Index s : above_) forwardNode(static_cast<std::size_t>(s), w, f, nullptr, -1);
}

void MultifrontalLu::backward() {
  float* w = work_.data();
  std::vector<float> xb;
  for (std::size_t k = above_.size(); k-- > 0;) backwardNode(static_cast<std::size_t>(above_[k]), w, xb);
#pragma omp parallel
  {
    std::vector<float> x;
    for (int g = omp_get_thread_num(); g < 2; g += omp_get_num_threads())
      for (std::size_t k = group_[static_cast<std::size_t>(g)].size(); k-- > 0;)
        backwardNode(static_cast<std::size_t>(group_[static_cast<std::size_t>(g)][k]), w, x);
  }
}

void MultifrontalLu::condense(std::span<const double> b, std::span<double> reduced) {
  require(static_cast<std::int64_t>(b.size()) == n_ && static_cast<std::int64_t>(reduced.size()) == z_ && z_ > 0,
          "multifrontal LU: condense needs a Schur set and full-length b");
  work_.resize(static_cast<std::size_t>(n_));
  for (std::size_t u = 0; u < b.size(); ++u) work_[static_cast<std::size_t>(internal_[u])] = static_cast<float>(b[u]);
  forward();
  for (std::size_t t = 0; t < reduced.size(); ++t) reduced[t] = work_[static_cast<std::size_t>(nF_) + t];
}

void MultifrontalLu::expand(std::span<const double> xZ, std::span<double> x) {
  require(static_cast<std::int64_t>(xZ.size()) == z_ && static_cast<std::int64_t>(x.size()) == n_,
          "multifrontal LU: expand needs x_Z and a full-length x");
  for (std::size_t t = 0; t < xZ.size(); ++t) work_[static_cast<std::size_t>(nF_) + t] = static_cast<float>(xZ[t]);
  backward();
  for (std::size_t u = 0; u < x.size(); ++u) x[u] = work_[static_cast<std::size_t>(internal_[u])];
}

void MultifrontalLu::solve(std::span<const double> b, std::span<double> x) {
  require(z_ == 0 && static_cast<std::int64_t>(b.size()) == n_ && static_cast<std::int64_t>(x.size()) == n_,
          "multifrontal LU: solve() is for a factorization without Schur set");
  work_.resize(static_cast<std::size_t>(n_));
  for (std::size_t u = 0; u < b.size(); ++u) work_[static_cast<std::size_t>(internal_[u])] = static_cast<float>(b[u]);
  forward();
  backward();
  for (std::size_t u = 0; u < x.size(); ++u) x[u] = work_[static_cast<std::size_t>(internal_[u])];
}

}  // namespace peristep
