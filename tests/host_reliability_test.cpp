// Nothing lost, nothing hanging: two runs writing one output name, scene paths that are not files,
// sample plans too large to build, damaged and half-written stored samples.
#include <catch2/catch.hpp>

#include <chrono>
#include <sstream>
#include <thread>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

// Test 1 on a grid fine enough that a run lasts a few seconds.
const std::string kSlowScene = R"(
[parameters]
scene = "smooth"
nx = 97
ny = 97
[loading]
input = "loadFactor"
from = 0.0
to = 1.0
steps = 12
)";

// Test 1's collocation scene on a small grid.
const std::string kSampleScene = R"(
[parameters]
scene = "smooth"
nx = 17
ny = 17
xi = [0.0]
[loading]
input = "loadFactor"
from = 0.0
to = 1.0
steps = 1
)";

ProcessResult peristep(const fs::path& cwd, std::vector<std::string> args) {
  args.insert(args.begin(), PERISTEP_HOST_BINARY);
  args.insert(args.end(), {"--fmu", PERISTEP_FMU});
  return runProcess(args, cwd);
}

}  // namespace

TEST_CASE("reliability: two runs writing one output name at once: one refused, the other's file opens",
          "[host][reliability]") {
  TempDir dir;
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  writeText(dir / "slow.toml", kSlowScene);
  const std::string out = (dir / "out.h5").string(), scene = (dir / "slow.toml").string();
  ProcessResult first, second;
  std::thread runner([&] { first = peristep(dir / "a", {"run", scene, "--out", out}); });
  // The second starts once the first has taken the name (its lock file appears before the set-up).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out + ".lock") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const bool overlapped = fs::exists(out + ".lock");
  second = peristep(dir / "b", {"run", scene, "--out", out});
  runner.join();
  INFO("first:\n" << first.out << first.err << "\nsecond:\n" << second.out << second.err);
  REQUIRE(overlapped);
  CHECK(first.exitCode == 0);
  CHECK(second.exitCode == 2);
  CHECK_THAT(second.err, Contains("another peristep process is writing this output"));
  const hid_t f = openHdf5(out);
  REQUIRE(f >= 0);
  CHECK(readDataset(f, "/fields/ux").shape.size() == 3);
  H5Fclose(f);
  CHECK_FALSE(fs::exists(out + ".lock"));  // released and removed
  // The name is free again.
  CHECK(peristep(dir / "b", {"run", scene, "--out", out}).exitCode == 0);
}

TEST_CASE("reliability: a scene path that is not a regular file is refused at once", "[host][reliability]") {
  TempDir dir;
  for (const std::string path : {std::string("."), std::string("/dev/zero")}) {
    INFO(path);
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = peristep(dir.path(), {"run", path, "--out", "out.h5"});
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.err, Contains("not a regular file"));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(30));
    CHECK_FALSE(fs::exists(dir / "out.h5"));
  }
}

TEST_CASE("reliability: sample plans too large are refused before they are built, with the count",
          "[host][reliability]") {
  TempDir dir;
  writeText(dir / "kl.toml", R"(
[parameters]
scene = "klPlate"
nx = 9
ny = 9
nModes = 20
[loading]
input = "loadFactor"
from = 0.0
to = 1.0
steps = 1
)");
  const auto refusal = [&](const std::vector<std::string>& rule) {
    std::vector<std::string> args{"sample", "kl.toml", "--out", "study.h5"};
    args.insert(args.end(), rule.begin(), rule.end());
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = peristep(dir.path(), args);
    INFO(r.out << r.err);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.err, Contains("samples, more than the 1000000 a study may hold"));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(60));
    return r.err;
  };
  CHECK_THAT(refusal({"--rule", "smolyak", "--level", "40"}), Contains("--rule smolyak at level 40 in 20"));
  CHECK_THAT(refusal({"--rule", "tensor", "--level", "100000000"}), Contains("--rule tensor at level 100000000"));
  CHECK_THAT(refusal({"--rule", "smolyak", "--level", "5"}), Contains("plans about 7.48e+06 samples"));
}

TEST_CASE("reliability: a damaged stored sample is recomputed with a warning, a dead run's temporaries removed",
          "[host][reliability]") {
  TempDir dir;
  writeText(dir / "t1.toml", kSampleScene);
  const std::vector<std::string> study{"sample", "t1.toml", "--rule", "tensor", "--level", "3", "--out", "study.h5"};
  const ProcessResult clean = peristep(dir.path(), study);
  REQUIRE(clean.exitCode == 0);
  const std::string statistics = readText(dir / "study.csv");
  std::vector<fs::path> stored;
  for (const auto& e : fs::directory_iterator(dir / "study.samples"))
    if (e.path().extension() == ".bin") stored.push_back(e.path());
  REQUIRE(stored.size() == 3);

  // One byte flipped in the middle of a sample; a temporary of a process that no longer exists.
  std::string bytes = readText(stored[1]);
  bytes[bytes.size() / 2] ^= 0x40;
  writeText(stored[1], bytes);
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  const fs::path stale = stored[0].string() + "." + host + ".999999999.tmp";
  writeText(stale, "half a sample");

  const ProcessResult again = peristep(dir.path(), study);
  INFO(again.out << again.err);
  REQUIRE(again.exitCode == 0);
  CHECK_THAT(again.err, Contains(stored[1].filename().string() + " is damaged (checksum mismatch)"));
  CHECK_FALSE(fs::exists(stale));
  // Same statistics (every column but "computed" and "seconds"), one sample computed again.
  const auto cells = [](const std::string& csv) {
    std::vector<std::string> out;
    std::istringstream row(csv.substr(csv.find('\n') + 1));
    for (std::string c; std::getline(row, c, ',');) out.push_back(c);
    return out;
  };
  std::vector<std::string> before = cells(statistics), after = cells(readText(dir / "study.csv"));
  REQUIRE(before.size() == after.size());
  REQUIRE(after.size() > 9);
  CHECK(after[2] == "1");
  before[2] = after[2] = before[7] = after[7] = "";
  CHECK(before == after);
}
