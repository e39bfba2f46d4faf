// `peristep sample` over MPI (mpirun -n 2 --oversubscribe) and as batch-array shards: the same CSV and
// the same statistics bit for bit as the serial run, and a study killed part-way and restarted under
// mpirun recomputes no finished sample (the store's files keep their modification times).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <map>
#include <sstream>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

std::vector<std::string> sampleArgs(const std::vector<std::string>& args) {
  std::vector<std::string> all{PERISTEP_HOST_BINARY, "sample"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--fmu", PERISTEP_FMU});
  return all;
}

// mpirun -n 2 --oversubscribe; CI runs as root, which Open MPI refuses unless told. `exitAfter` > 0 makes
// every rank end abruptly after computing that many samples (PERISTEP_SAMPLE_EXIT_AFTER).
ProcessResult mpirun(const fs::path& dir, const std::vector<std::string>& args, int exitAfter = 0) {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  if (exitAfter > 0) setenv("PERISTEP_SAMPLE_EXIT_AFTER", std::to_string(exitAfter).c_str(), 1);
  std::vector<std::string> all{PERISTEP_MPIEXEC, "-n", "2", "--oversubscribe"};
  if (exitAfter > 0) all.insert(all.end(), {"-x", "PERISTEP_SAMPLE_EXIT_AFTER"});
  const std::vector<std::string> sample = sampleArgs(args);
  all.insert(all.end(), sample.begin(), sample.end());
  const ProcessResult r = runProcess(all, dir);
  unsetenv("PERISTEP_SAMPLE_EXIT_AFTER");
  return r;
}

// The same study serially on two threads in `serial` and under mpirun -n 2 in `parallel`; both must succeed.
void serialAndMpirun(const fs::path& serial, const fs::path& parallel, const std::vector<std::string>& args) {
  std::vector<std::string> twoThreads = args;
  twoThreads.insert(twoThreads.end(), {"--threads", "2"});
  const ProcessResult one = runProcess(sampleArgs(twoThreads), serial);
  INFO("serial:\n" << one.out << one.err);
  REQUIRE(one.exitCode == 0);
  const ProcessResult two = mpirun(parallel, args);
  INFO("mpirun:\n" << two.out << two.err);
  REQUIRE(two.exitCode == 0);
  CHECK_THAT(two.out, Contains("2 MPI ranks"));
}

// The CSV with the named columns blanked (wall time differs between runs).
std::string csvWithout(const fs::path& file, const std::vector<std::string>& columns) {
  std::istringstream in(readText(file));
  std::string header, out;
  std::getline(in, header);
  std::vector<bool> drop;
  {
    std::istringstream h(header);
    for (std::string c; std::getline(h, c, ',');)
      drop.push_back(std::find(columns.begin(), columns.end(), c) != columns.end());
  }
  out = header + '\n';
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::size_t k = 0;
    for (std::string c; std::getline(s, c, ','); ++k) out += (k ? "," : "") + (k < drop.size() && drop[k] ? "*" : c);
    out += '\n';
  }
  return out;
}

// Every sample file of a store with its modification time.
std::map<std::string, fs::file_time_type> storeFiles(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> files;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".bin") files[e.path().filename().string()] = fs::last_write_time(e.path());
  return files;
}

void checkSameStatistics(const fs::path& a, const fs::path& b, const std::vector<std::string>& datasets) {
  for (const std::string& name : datasets) {
    const hid_t fa = openHdf5(a), fb = openHdf5(b);
    REQUIRE(fa >= 0);
    REQUIRE(fb >= 0);
    const Dataset x = readDataset(fa, name), y = readDataset(fb, name);
    H5Fclose(fa);
    H5Fclose(fb);
    INFO(name);
    REQUIRE(!x.values.empty());
    CHECK(x.values == y.values);  // bit for bit
  }
}

const std::vector<std::string> kStatistics{"/level_2/mean/ux", "/level_2/std/uy", "/level_2/pce_std/ux",
                                           "/level_2/mean/errorL2", "/level_1/pce_std/errorL2"};

}  // namespace

// The serial run on two threads, each rank of mpirun on the one core it is bound to: the same bits
// whatever the thread count (the component's sums in fixed blocks, OpenBLAS on one thread).
TEST_CASE("mpi: mpirun -n 2 gives the serial run's CSV (apart from wall time) and statistics bit for bit",
          "[host][sample][mpi]") {
  const ScopedEnv oneThreadPerRank("OMP_NUM_THREADS", "1");  // the serial run overrides it
  TempDir serial, parallel;
  for (const TempDir* d : {&serial, &parallel}) writeText(*d / "t2.toml", sceneOnGrid("composite_sampling.toml", 33));
  serialAndMpirun(serial.path(), parallel.path(), {"t2.toml", "--rule", "smolyak", "--levels", "1,2", "--out", "s.h5"});
  CHECK(storeFiles(parallel / "s.samples").size() == 17);  // 5 + 17 points, the 5 shared
  CHECK(csvWithout(parallel / "s.csv", {"seconds"}) == csvWithout(serial / "s.csv", {"seconds"}));
  checkSameStatistics(serial / "s.h5", parallel / "s.h5", kStatistics);
}

TEST_CASE("mpi: a study killed part-way under mpirun and restarted recomputes no finished sample",
          "[host][sample][mpi]") {
  TempDir dir;
  writeText(dir / "t1.toml", sceneOnGrid("smooth_sampling.toml", 17));
  const std::vector<std::string> args{"t1.toml", "--rule", "tensor", "--level", "12", "--out", "study.h5"};
  const ScopedEnv tmp("TMPDIR", privateTmp(dir).string());
  const ProcessResult killed = mpirun(dir.path(), args, 2);  // each rank ends after its 2nd sample
  INFO("killed run:\n" << killed.out << killed.err);
  CHECK(killed.exitCode != 0);
  const auto before = storeFiles(dir / "study.samples");
  INFO("samples finished before the kill: " << before.size());
  REQUIRE(before.size() >= 2);
  REQUIRE(before.size() <= 4);
  CHECK(!fs::exists(dir / "study.csv"));

  const ProcessResult resumed = mpirun(dir.path(), args);
  INFO("restarted:\n" << resumed.out << resumed.err);
  REQUIRE(resumed.exitCode == 0);
  const auto after = storeFiles(dir / "study.samples");
  CHECK(after.size() == 12);
  for (const auto& [name, time] : before) {  // untouched: not recomputed, not rewritten
    REQUIRE(after.count(name) == 1);
    CHECK(after.at(name) == time);
  }
  const std::string csv = readText(dir / "study.csv");
  std::istringstream rows(csv);
  std::string header, row;
  std::getline(rows, header);
  std::getline(rows, row);
  INFO(csv);
  CHECK(row.rfind("12,12," + std::to_string(12 - before.size()) + ",", 0) == 0);  // level, samples, computed
}

TEST_CASE("mpi-free shards: --shard 1/2 and 2/2 then --merge give the serial statistics and --merge names what is missing",
          "[host][sample][mpi][shard]") {
  TempDir serial, shards;
  for (const TempDir* d : {&serial, &shards}) writeText(*d / "t2.toml", sceneOnGrid("composite_sampling.toml", 9));
  const std::vector<std::string> args{"t2.toml", "--rule", "smolyak", "--level", "2", "--out", "s.h5"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> all = args;
    all.insert(all.end(), extra.begin(), extra.end());
    return runProcess(sampleArgs(all), shards.path());
  };
  REQUIRE(runProcess(sampleArgs(args), serial.path()).exitCode == 0);

  const ProcessResult first = with({"--shard", "1/2"});
  INFO(first.out << first.err);
  REQUIRE(first.exitCode == 0);
  CHECK(!fs::exists(shards / "s.csv"));  // a shard writes samples only
  CHECK(storeFiles(shards / "s.samples").size() == 9);  // samples 1, 3, ..., 17
  const ProcessResult early = with({"--merge"});
  CHECK(early.exitCode == 1);
  CHECK_THAT(early.err, Contains("8 of 17 samples are not in") && Contains("samples 2, 4, 6, 8, 10, 12, 14, 16"));

  REQUIRE(with({"--shard", "2/2"}).exitCode == 0);
  CHECK(storeFiles(shards / "s.samples").size() == 17);
  const ProcessResult merged = with({"--merge"});
  INFO(merged.out << merged.err);
  REQUIRE(merged.exitCode == 0);
  // The merge computed nothing itself: only "computed" and the wall time differ from the serial run.
  CHECK(csvWithout(shards / "s.csv", {"seconds", "computed"}) == csvWithout(serial / "s.csv", {"seconds", "computed"}));
  checkSameStatistics(serial / "s.h5", shards / "s.h5", {"/level_2/mean/ux", "/level_2/std/uy", "/level_2/pce_std/ux"});

  CHECK(with({"--shard", "3/2"}).exitCode == 2);
  CHECK(with({"--shard", "1/2", "--merge"}).exitCode == 2);
}

// Multilevel Monte Carlo chooses its sample counts from variances and costs; with the costs given
// (--level-costs) the choice is the same in every run, and so is every number.
TEST_CASE("mpi: mpirun -n 2 gives the serial multilevel estimate bit for bit", "[host][sample][mpi][mlmc]") {
  const ScopedEnv oneThreadPerRank("OMP_NUM_THREADS", "1");
  TempDir serial, parallel;
  for (const TempDir* d : {&serial, &parallel}) writeText(*d / "t3.toml", sceneOnGrid("interface_crack_sampling.toml", 17));
  serialAndMpirun(serial.path(), parallel.path(), {"t3.toml", "--rule", "mlmc", "--grids", "2", "--quantity", "reactionTopY",
                                                   "--se", "0.01", "--level-costs", "1,4", "--out", "ml.h5"});
  CHECK(csvWithout(parallel / "ml.csv", {"fine_s", "coarse_s"}) == csvWithout(serial / "ml.csv", {"fine_s", "coarse_s"}));
  CHECK(csvWithout(parallel / "ml_summary.csv", {"sample_seconds", "threads_per_sample", "plain_mc_seconds"}) ==
        csvWithout(serial / "ml_summary.csv", {"sample_seconds", "threads_per_sample", "plain_mc_seconds"}));
}
