#include "linalg/schur_factorization.hpp"

#include <dmumps_c.h>
#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "linalg/multifrontal_lu.hpp"

namespace peristep {

class SchurFactorization::Backend {
 public:
  virtual ~Backend() = default;
  virtual void factorize(const CsrMatrix& A, std::span<const double> scale,
                         const std::vector<std::int64_t>& schurUnknowns, const std::vector<std::int32_t>& position) = 0;
  virtual void condense(std::span<const double> b, std::span<double> reduced) = 0;
  virtual void expand(std::span<const double> xZ, std::span<double> x) = 0;
  virtual void solve(std::span<const double> b, std::span<double> x) = 0;
  std::vector<double> schur;  // column-major
  std::int64_t factorEntries = 0;
};

namespace {

constexpr int kInitialize = -1, kTerminate = -2, kAnalyze = 1, kFactorize = 2, kSolve = 3;
constexpr int kHostWorks = 1, kUnsymmetric = 0, kCommSelf = -987654;  // MUMPS' sequential library

// Memory mapped once and kept: MUMPS's main work array across factorizations.
struct Workspace {
  void* data = nullptr;
  std::size_t bytes = 0;
  Workspace() = default;
  Workspace& operator=(Workspace&& o) noexcept {
    std::swap(data, o.data);
    std::swap(bytes, o.bytes);
    return *this;
  }
  ~Workspace() {
    if (data) munmap(data, bytes);
  }
};

// Square transposes in tiles that stay in cache (element by element, the strided side misses the cache and
// the TLB at every entry: about 19 ms for a zone of 1400 unknowns at h = 8 um, 3 ms in tiles).
constexpr std::size_t kTile = 64;

void transposeInPlace(std::vector<double>& a, std::size_t n) {
#pragma omp parallel for schedule(dynamic)
  for (std::size_t ib = 0; ib < n; ib += kTile)
    for (std::size_t jb = ib; jb < n; jb += kTile)
      for (std::size_t i = ib; i < std::min(ib + kTile, n); ++i)
        for (std::size_t j = std::max(jb, i + 1); j < std::min(jb + kTile, n); ++j) std::swap(a[i * n + j], a[j * n + i]);
}

// MUMPS' double-precision factors (dmumps).
class Mumps final : public SchurFactorization::Backend {
 public:
  using Real = double;

  Mumps() {
    id_.job = kInitialize;
    id_.par = kHostWorks;
    id_.sym = kUnsymmetric;
    id_.comm_fortran = kCommSelf;
    dmumps_c(&id_);
    if (id_.infog[0] < 0)
      throw SolverFailure("mumps: initialization failed with INFOG(1) = " + std::to_string(id_.infog[0]));
    for (int stream : {1, 2, 3}) icntl(stream) = -1;  // no output: the component logs through FMI only
    icntl(4) = 0;
    // The analysis must depend on the pattern and the Schur set only, not on values (it is reused across
    // factorizations, and a restored run must factor as the original): no value-based column permutation
    // or scaling (the caller's D scales the matrix).
    icntl(6) = 0;
    icntl(8) = 0;
    // The caller's ordering: with a Schur set MUMPS falls back to AMD (2.3x the factors of nested
    // dissection at h = 4 um), Debian's MUMPS has no METIS, and its SCOTCH orders differently from run to
    // run (threads), so that two runs of the same specimen would not repeat each other bit for bit.
    icntl(7) = 1;
    icntl(14) = 40;  // workspace margin for delayed pivots, in percent
  }
  ~Mumps() override {
    id_.job = kTerminate;
    dmumps_c(&id_);
  }

  void factorize(const CsrMatrix& A, std::span<const double> scale, const std::vector<std::int64_t>& schurUnknowns,
                 const std::vector<std::int32_t>& position) override {
    require(A.rows == A.cols, "mumps: the matrix must be square");
    if (rowIndex_.empty()) {
      rowIndex_.resize(static_cast<std::size_t>(A.nonZeros()));
      colIndex_.resize(rowIndex_.size());
      for (std::int64_t r = 0; r < A.rows; ++r)
        for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) {
          rowIndex_[static_cast<std::size_t>(k)] = static_cast<int>(r + 1);
          colIndex_[static_cast<std::size_t>(k)] = static_cast<int>(A.col[static_cast<std::size_t>(k)] + 1);
        }
    }
    require(static_cast<std::size_t>(A.nonZeros()) == rowIndex_.size(), "mumps: the sparsity pattern changed");
    id_.n = static_cast<int>(A.rows);
    id_.nnz = A.nonZeros();
    id_.irn = rowIndex_.data();
    id_.jcn = colIndex_.data();
    require(static_cast<std::int64_t>(scale.size()) == A.rows, "mumps: one scale factor per unknown");
    std::vector<Real> values(rowIndex_.size());  // D A D in Real, read by MUMPS while it factorizes only
    for (std::int64_t r = 0; r < A.rows; ++r)
      for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k)
        values[static_cast<std::size_t>(k)] = static_cast<Real>(
            A.value[k] * (scale[static_cast<std::size_t>(r)] * scale[static_cast<std::size_t>(A.col[k])]));
    id_.a = values.data();
    require(static_cast<std::int64_t>(position.size()) == A.rows, "mumps: one pivot position per unknown");
    std::vector<int> order(position.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = position[i] + 1;
    if (!analyzed_ || schurUnknowns != schurUnknowns_ || order != position_) {
      schurUnknowns_ = schurUnknowns;
      position_ = std::move(order);
      id_.perm_in = position_.data();
      schurList_.resize(schurUnknowns_.size());
      for (std::size_t i = 0; i < schurList_.size(); ++i) schurList_[i] = static_cast<int>(schurUnknowns_[i] + 1);
      const int z = static_cast<int>(schurList_.size());
      icntl(19) = z > 0 ? 1 : 0;  // centralized Schur complement, by rows
      id_.size_schur = z;
      id_.listvar_schur = z > 0 ? schurList_.data() : nullptr;
      call(kAnalyze, "analysis");
      analyzed_ = true;
    }
    const std::size_t z = schurUnknowns_.size();
    schur.assign(z * z, 0.0);
    id_.schur = z > 0 ? schur.data() : nullptr;
    id_.schur_lld = static_cast<int>(z);
    call(kFactorize, "numeric factorization");
    id_.a = nullptr;  // the solves do not read A (no iterative refinement or error analysis: ICNTL(10), (11) = 0)
    id_.schur = nullptr;
    factorEntries = id_.infog[28] >= 0 ? id_.infog[28] : -static_cast<std::int64_t>(id_.infog[28]) * 1000000;
    transposeInPlace(schur, z);  // by rows -> column-major
  }

  void condense(std::span<const double> b, std::span<double> reduced) override {
    require(reduced.size() == schurUnknowns_.size() && !schurUnknowns_.empty(), "mumps: condense needs a Schur set");
    rhs_.assign(b.begin(), b.end());
    std::vector<Real> out(reduced.size());
    id_.rhs = rhs_.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.redrhs = out.data();
    id_.lredrhs = static_cast<int>(reduced.size());
    icntl(26) = 1;  // forward elimination only; b_Z - A_ZF A_FF^-1 b_F into REDRHS
    call(kSolve, "condensation");
    std::copy(out.begin(), out.end(), reduced.begin());
  }

  void expand(std::span<const double> xZ, std::span<double> x) override {
    std::vector<Real> reduced(xZ.begin(), xZ.end());
    id_.rhs = rhs_.data();  // as condense() left it
    id_.redrhs = reduced.data();
    id_.lredrhs = static_cast<int>(reduced.size());
    icntl(26) = 2;  // backward substitution with x_Z given
    call(kSolve, "expansion");
    icntl(26) = 0;
    std::copy(rhs_.begin(), rhs_.end(), x.begin());
  }

  void solve(std::span<const double> b, std::span<double> x) override {
    require(schurUnknowns_.empty(), "mumps: solve() is for a factorization without Schur set");
    rhs_.assign(b.begin(), b.end());
    id_.rhs = rhs_.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    icntl(26) = 0;
    call(kSolve, "solve");
    std::copy(rhs_.begin(), rhs_.end(), x.begin());
    for (double v : x)
      if (!std::isfinite(v)) throw SolverFailure("mumps: solution is not finite (singular system?)");
  }

 private:
  int& icntl(int i) { return id_.icntl[i - 1]; }  // 1-based in MUMPS' documentation

  void call(int job, const char* what) {
    for (int attempt = 0;; ++attempt) {
      if (job == kFactorize) useWorkspace();
      id_.job = job;
      dmumps_c(&id_);
      if (job == kAnalyze && id_.infog[0] >= 0)  // INFO(8): entries of S, in millions when negative
        workspaceEstimate_ = id_.info[7] >= 0 ? id_.info[7] : -static_cast<std::int64_t>(id_.info[7]) * 1000000;
      // -8/-9: the estimated workspace was too small (more delayed pivots than analysed): grow it, retry.
      if ((id_.infog[0] == -8 || id_.infog[0] == -9) && job == kFactorize && attempt < 4) {
        icntl(14) *= 2;
        continue;
      }
      if (id_.infog[0] < 0)
        throw SolverFailure(std::string("mumps: ") + what + " failed with INFOG(1) = " + std::to_string(id_.infog[0]) +
                            ", INFOG(2) = " + std::to_string(id_.infog[1]));
      return;
    }
  }

  void useWorkspace() {
    // MUMPS's main work array S holds the factors and the stack of frontal matrices: ~3 GB at h = 2 um
    // in double. Its own allocation maps fresh pages at every factorization (1.1 million page faults each,
    // 330 s of system time in a full-size run); this one is kept, grown when a zone needs more, and asks
    // for huge pages.
    const std::int64_t entries = workspaceEstimate_ * (100 + icntl(14)) / 100;
    if (entries <= 0 || entries > std::numeric_limits<int>::max()) {  // LWK_USER is a 32-bit count
      id_.wk_user = nullptr;
      id_.lwk_user = 0;
      return;
    }
    const std::size_t bytes = static_cast<std::size_t>(entries) * sizeof(Real);
    if (bytes > workspace_.bytes) {
      workspace_ = Workspace{};
      void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED) throw std::bad_alloc();
      madvise(p, bytes, MADV_HUGEPAGE);  // a hint: without transparent huge pages it is plain memory
      workspace_.data = p;
      workspace_.bytes = bytes;
    }
    id_.wk_user = static_cast<Real*>(workspace_.data);
    // All of it, not this zone's estimate: MUMPS stacks the frontal matrices down from the end of S, so an end
    // that moved with each zone's estimate put every smaller zone's stack on pages no zone had touched yet, and
    // the resident part of S grew over a run (h = 2 um, f = 0.8: run peak 3045 -> 2953 MiB).
    id_.lwk_user = static_cast<int>(workspace_.bytes / sizeof(Real));
  }

  Workspace workspace_;  // outlives the MUMPS instance: the destructor terminates MUMPS first
  DMUMPS_STRUC_C id_{};
  std::vector<int> rowIndex_, colIndex_;  // 1-based coordinates of A's entries
  std::vector<std::int64_t> schurUnknowns_;
  std::vector<int> schurList_, position_;  // 1-based, for MUMPS
  std::vector<Real> rhs_;
  bool analyzed_ = false;
  std::int64_t workspaceEstimate_ = 0;  // MUMPS' estimate of S after the analysis, entries
};

// Single precision: the project's own multifrontal LU (linalg/multifrontal_lu.hpp), whose substitutions read
// the factors at the memory bound; MUMPS' own single-precision solves read them at a third of it
// (docs/decisions/0001-own-single-precision-lu.md).
class OwnFrontal final : public SchurFactorization::Backend {
 public:
  void factorize(const CsrMatrix& A, std::span<const double> scale, const std::vector<std::int64_t>& schurUnknowns,
                 const std::vector<std::int32_t>& position) override {
    if (!lu_.analyzed() || schurUnknowns != schurUnknowns_ || position != position_) {
      schurUnknowns_ = schurUnknowns;
      position_ = position;
      lu_.analyze(A, position_, schurUnknowns_.size(), schurUnknowns_);
    }
    lu_.factorize(A, scale, schur);
    factorEntries = lu_.factorEntries();
  }
  void condense(std::span<const double> b, std::span<double> reduced) override { lu_.condense(b, reduced); }
  void expand(std::span<const double> xZ, std::span<double> x) override { lu_.expand(xZ, x); }
  void solve(std::span<const double> b, std::span<double> x) override {
    lu_.solve(b, x);
    for (double v : x)
      if (!std::isfinite(v)) throw SolverFailure("multifrontal LU: solution is not finite (singular system?)");
  }

 private:
  MultifrontalLu lu_;
  std::vector<std::int64_t> schurUnknowns_;
  std::vector<std::int32_t> position_;
};

}  // namespace

SchurFactorization::SchurFactorization(FactorPrecision precision) { setPrecision(precision); }

void SchurFactorization::setPrecision(FactorPrecision precision) {
  precision_ = precision;
  if (precision == FactorPrecision::Single)
    backend_ = std::make_unique<OwnFrontal>();
  else
    backend_ = std::make_unique<Mumps>();
}

SchurFactorization::~SchurFactorization() = default;

void SchurFactorization::factorize(const CsrMatrix& A, std::span<const double> scale,
                                   const std::vector<std::int64_t>& schurUnknowns,
                                   const std::vector<std::int32_t>& position) {
  backend_->factorize(A, scale, schurUnknowns, position);
}

const std::vector<double>& SchurFactorization::schurComplement() const { return backend_->schur; }
std::vector<double> SchurFactorization::takeSchurComplement() { return std::move(backend_->schur); }
std::int64_t SchurFactorization::factorEntries() const { return backend_->factorEntries; }

void SchurFactorization::condense(std::span<const double> b, std::span<double> reduced) {
  backend_->condense(b, reduced);
}
void SchurFactorization::expand(std::span<const double> xZ, std::span<double> x) { backend_->expand(xZ, x); }
void SchurFactorization::solve(std::span<const double> b, std::span<double> x) { backend_->solve(b, x); }

}  // namespace peristep
