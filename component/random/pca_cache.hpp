#pragma once
// Process-wide cache of PCA modes, so that the samples of one study (and several FMU instances in one
// process) share the modes instead of streaming 20,000 realizations again for every sample. The caller
// builds the key from everything the modes depend on (grid, fraction, seed base, n, k, ...).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "random/microstructure_pca.hpp"

namespace peristep {

// The modes stored under key, computing them with `compute` on the first request. Thread-safe:
// concurrent requests for one key wait for a single computation; requests for other keys proceed. If
// compute throws, every waiting caller gets the exception and nothing is stored (a later call retries).
std::shared_ptr<const PcaModes> cachedPca(const std::string& key, const std::function<PcaModes()>& compute);

// The modes under key if they are stored (finished), else nullptr. Never computes.
std::shared_ptr<const PcaModes> findCachedPca(const std::string& key);

// Number of stored entries, and forgetting them all (held shared_ptrs stay valid).
std::size_t pcaCacheSize();
void clearPcaCache();

}  // namespace peristep
