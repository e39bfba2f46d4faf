#include "random/pca_cache.hpp"

#include <future>
#include <map>
#include <mutex>

namespace peristep {
namespace {

using Entry = std::shared_future<std::shared_ptr<const PcaModes>>;

struct Cache {
  std::mutex mutex;
  std::map<std::string, Entry, std::less<>> entries;
};

Cache& cache() {
  static Cache instance;
  return instance;
}

bool ready(const Entry& e) { return e.wait_for(std::chrono::seconds(0)) == std::future_status::ready; }

}  // namespace

std::shared_ptr<const PcaModes> cachedPca(const std::string& key, const std::function<PcaModes()>& compute) {
  Cache& c = cache();
  std::promise<std::shared_ptr<const PcaModes>> promise;
  Entry entry;
  {
    std::lock_guard lock(c.mutex);
    if (const auto it = c.entries.find(key); it != c.entries.end()) {
      entry = it->second;
    } else {
      entry = promise.get_future().share();
      c.entries.emplace(key, entry);
      entry = {};  // this caller computes
    }
  }
  if (entry.valid()) return entry.get();  // another caller computes (or has computed): wait for it

  // Compute outside the lock; publish the result or the exception to every waiter.
  try {
    auto modes = std::make_shared<const PcaModes>(compute());
    promise.set_value(modes);
    return modes;
  } catch (...) {
    {
      std::lock_guard lock(c.mutex);
      c.entries.erase(key);
    }
    promise.set_exception(std::current_exception());
    throw;
  }
}

std::shared_ptr<const PcaModes> findCachedPca(const std::string& key) {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  const auto it = c.entries.find(key);
  if (it == c.entries.end() || !ready(it->second)) return nullptr;
  return it->second.get();
}

std::size_t pcaCacheSize() {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  std::size_t n = 0;
  for (const auto& [key, entry] : c.entries) n += ready(entry);
  return n;
}

void clearPcaCache() {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  // Entries still being computed stay: their computing caller will publish to them.
  std::erase_if(c.entries, [](const auto& kv) { return ready(kv.second); });
}

}  // namespace peristep
