#include "solvers/schur_factorization.hpp"

#include <dmumps_c.h>
#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <string>

#include "core/errors.hpp"

namespace peristep {

struct SchurFactorization::Mumps {
  DMUMPS_STRUC_C id{};
};

namespace {
constexpr int kInitialize = -1, kTerminate = -2, kAnalyze = 1, kFactorize = 2, kSolve = 3;
constexpr int kHostWorks = 1, kUnsymmetric = 0, kCommSelf = -987654;  // MUMPS' sequential library
// ICNTL / INFOG are 1-based in MUMPS' documentation.
int& icntl(DMUMPS_STRUC_C& id, int i) { return id.icntl[i - 1]; }
}  // namespace

SchurFactorization::SchurFactorization() : mumps_(std::make_unique<Mumps>()) {
  DMUMPS_STRUC_C& id = mumps_->id;
  id.job = kInitialize;
  id.par = kHostWorks;
  id.sym = kUnsymmetric;
  id.comm_fortran = kCommSelf;
  dmumps_c(&id);
  if (id.infog[0] < 0) throw SolverFailure("mumps: initialization failed with INFOG(1) = " + std::to_string(id.infog[0]));
  for (int stream : {1, 2, 3}) icntl(id, stream) = -1;  // no output: the component logs through FMI only
  icntl(id, 4) = 0;
  // The analysis must depend on the pattern and the Schur set only, not on values (it is reused across
  // factorizations, and a restored run must factor as the original): no value-based column permutation
  // or scaling (the caller scales the matrix).
  icntl(id, 6) = 0;
  icntl(id, 8) = 0;
  // The caller's ordering: with a Schur set MUMPS falls back to AMD (2.3x the factors of nested
  // dissection at h = 4 um), Debian's MUMPS has no METIS, and its SCOTCH orders differently from run to
  // run (threads), so that two runs of the same specimen would not repeat each other bit for bit.
  icntl(id, 7) = 1;
  icntl(id, 14) = 40;  // workspace margin for delayed pivots, in percent
}

SchurFactorization::~SchurFactorization() {
  mumps_->id.job = kTerminate;
  dmumps_c(&mumps_->id);
}

void SchurFactorization::call(int job, const char* what) {
  DMUMPS_STRUC_C& id = mumps_->id;
  for (int attempt = 0;; ++attempt) {
    if (job == kFactorize) useWorkspace();
    id.job = job;
    dmumps_c(&id);
    if (job == kAnalyze && id.infog[0] >= 0)  // INFO(8): entries of S, in millions when negative
      workspaceEstimate_ = id.info[7] >= 0 ? id.info[7] : -static_cast<std::int64_t>(id.info[7]) * 1000000;
    // -8/-9: the estimated workspace was too small (more delayed pivots than analysed): grow it, retry.
    if ((id.infog[0] == -8 || id.infog[0] == -9) && job == kFactorize && attempt < 4) {
      icntl(id, 14) *= 2;
      continue;
    }
    if (id.infog[0] < 0)
      throw SolverFailure(std::string("mumps: ") + what + " failed with INFOG(1) = " + std::to_string(id.infog[0]) +
                          ", INFOG(2) = " + std::to_string(id.infog[1]));
    return;
  }
}

SchurFactorization::Workspace::~Workspace() {
  if (data) munmap(data, bytes);
}

void SchurFactorization::useWorkspace() {
  // MUMPS's main work array S holds the factors and the stack of frontal matrices: ~3 GB at h = 2 um. Its
  // own allocation maps fresh pages at every factorization (1.1 million page faults each, 330 s of system
  // time in a full-size run); this one is kept, grown when a zone needs more, and asks for huge pages.
  DMUMPS_STRUC_C& id = mumps_->id;
  const std::int64_t entries = workspaceEstimate_ * (100 + icntl(id, 14)) / 100;
  if (entries <= 0 || entries > std::numeric_limits<int>::max()) {  // LWK_USER is a 32-bit count
    id.wk_user = nullptr;
    id.lwk_user = 0;
    return;
  }
  const std::size_t bytes = static_cast<std::size_t>(entries) * sizeof(double);
  if (bytes > workspace_.bytes) {
    workspace_ = Workspace{};
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    madvise(p, bytes, MADV_HUGEPAGE);  // a hint: without transparent huge pages it is plain memory
    workspace_.data = p;
    workspace_.bytes = bytes;
  }
  id.wk_user = static_cast<double*>(workspace_.data);
  id.lwk_user = static_cast<int>(entries);
}

void SchurFactorization::factorize(const CsrMatrix& A, const std::vector<std::int64_t>& schurUnknowns,
                                   const std::vector<std::int32_t>& position) {
  DMUMPS_STRUC_C& id = mumps_->id;
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
  id.n = static_cast<int>(A.rows);
  id.nnz = A.nonZeros();
  id.irn = rowIndex_.data();
  id.jcn = colIndex_.data();
  id.a = const_cast<double*>(A.value.data());  // MUMPS reads A while it factorizes, it does not write it
  require(static_cast<std::int64_t>(position.size()) == A.rows, "mumps: one pivot position per unknown");
  std::vector<int> order(position.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = position[i] + 1;
  if (!analyzed_ || schurUnknowns != schurUnknowns_ || order != position_) {
    schurUnknowns_ = schurUnknowns;
    position_ = std::move(order);
    id.perm_in = position_.data();
    schurList_.resize(schurUnknowns_.size());
    for (std::size_t i = 0; i < schurList_.size(); ++i) schurList_[i] = static_cast<int>(schurUnknowns_[i] + 1);
    const int z = static_cast<int>(schurList_.size());
    icntl(id, 19) = z > 0 ? 1 : 0;  // centralized Schur complement, by rows
    id.size_schur = z;
    id.listvar_schur = z > 0 ? schurList_.data() : nullptr;
    call(kAnalyze, "analysis");
    analyzed_ = true;
  }
  const std::size_t z = schurUnknowns_.size();
  schur_.assign(z * z, 0.0);
  id.schur = z > 0 ? schur_.data() : nullptr;
  id.schur_lld = static_cast<int>(z);
  call(kFactorize, "numeric factorization");
  id.a = nullptr;  // the solves do not read A (no iterative refinement or error analysis: ICNTL(10), (11) = 0)
  id.schur = nullptr;
  for (std::size_t i = 0; i < z; ++i)  // by rows -> column-major, in place
    for (std::size_t j = i + 1; j < z; ++j) std::swap(schur_[i * z + j], schur_[j * z + i]);
}

void SchurFactorization::condense(std::span<const double> b, std::span<double> reduced) {
  DMUMPS_STRUC_C& id = mumps_->id;
  require(reduced.size() == schurUnknowns_.size() && !schurUnknowns_.empty(), "mumps: condense needs a Schur set");
  rhs_.assign(b.begin(), b.end());
  id.rhs = rhs_.data();
  id.nrhs = 1;
  id.lrhs = id.n;
  id.redrhs = reduced.data();
  id.lredrhs = static_cast<int>(reduced.size());
  icntl(id, 26) = 1;  // forward elimination only; b_Z - A_ZF A_FF^-1 b_F into REDRHS
  call(kSolve, "condensation");
}

void SchurFactorization::expand(std::span<const double> xZ, std::span<double> x) {
  DMUMPS_STRUC_C& id = mumps_->id;
  std::vector<double> reduced(xZ.begin(), xZ.end());
  id.rhs = rhs_.data();  // as condense() left it
  id.redrhs = reduced.data();
  id.lredrhs = static_cast<int>(reduced.size());
  icntl(id, 26) = 2;  // backward substitution with x_Z given
  call(kSolve, "expansion");
  icntl(id, 26) = 0;
  std::copy(rhs_.begin(), rhs_.end(), x.begin());
}

void SchurFactorization::solve(std::span<const double> b, std::span<double> x) {
  DMUMPS_STRUC_C& id = mumps_->id;
  require(schurUnknowns_.empty(), "mumps: solve() is for a factorization without Schur set");
  std::copy(b.begin(), b.end(), x.begin());
  id.rhs = x.data();
  id.nrhs = 1;
  id.lrhs = id.n;
  icntl(id, 26) = 0;
  call(kSolve, "solve");
  for (double v : x)
    if (!std::isfinite(v)) throw SolverFailure("mumps: solution is not finite (singular system?)");
}

}  // namespace peristep
