// `peristep sample`: collocation and Monte Carlo studies through the FMU, their errors against the exact
// moments (000 Sec. 4), the study files, and a sample loop killed part-way and restarted.
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <thread>

#include "fmu_archive.hpp"
#include "host_test_support.hpp"
#include "png_test_support.hpp"
#include "sample_plot.hpp"

using namespace host_test;
using peristep::host::samplePlotHeight;
using peristep::host::samplePlotWidth;
using Catch::Matchers::Contains;

namespace {

struct LevelRow {
  double level, samples, computed, errorMean, errorStd;
};

std::vector<LevelRow> readStudyCsv(const fs::path& file) {
  std::istringstream in(readText(file));
  std::string line;
  std::getline(in, line);
  REQUIRE(line.rfind("level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds", 0) == 0);
  std::vector<LevelRow> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream s(line);
    for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
    REQUIRE(cells.size() >= 5);
    const auto num = [](const std::string& c) { return c.empty() ? std::nan("") : std::stod(c); };
    rows.push_back({num(cells[0]), num(cells[1]), num(cells[2]), num(cells[3]), num(cells[4])});
  }
  return rows;
}

// scenes/<name> with the `key = value` lines of `changes` replaced (every key must be in the file).
std::string sceneText(const std::string& name, const std::vector<std::pair<std::string, std::string>>& changes) {
  std::istringstream in(readText(fs::path(PERISTEP_SOURCE_DIR) / "scenes" / name));
  std::string out;
  std::size_t replaced = 0;
  for (std::string line; std::getline(in, line);) {
    for (const auto& [key, value] : changes)
      if (line.rfind(key + " =", 0) == 0) line = key + " = " + value, ++replaced;
    out += line + '\n';
  }
  REQUIRE(replaced == changes.size());
  return out;
}

ProcessResult sample(const fs::path& dir, const std::vector<std::string>& args) {
  std::vector<std::string> all{PERISTEP_HOST_BINARY, "sample"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--fmu", PERISTEP_FMU});
  return runProcess(all, dir);
}

}  // namespace

TEST_CASE("peristep sample: Test 1 collocation errors fall 10x from 1 to 4 points (h = 1/64)", "[host][sample]") {
  for (const char* nu : {"0.3", "0.495"}) {
    TempDir dir;
    writeText(dir / "t1.toml", sceneText("smooth_sampling.toml", {{"poissonRatio", nu}}));
    const ProcessResult r = sample(dir.path(), {"t1.toml", "--rule", "tensor", "--levels", "1,2,3,4", "--out", "t1.h5"});
    INFO("nu = " << nu << "\nstdout:\n" << r.out << "\nstderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    const auto rows = readStudyCsv(dir / "t1.csv");
    REQUIRE(rows.size() == 4);
    for (std::size_t k = 0; k < 4; ++k) CHECK(rows[k].samples == static_cast<double>(k + 1));
    CHECK(rows[0].errorMean / rows[3].errorMean >= 10.0);
    CHECK(rows[0].errorStd / rows[3].errorStd >= 10.0);
    // Falling with every point for the mean (to ~1e-4 at 4 points, above the ~2e-5 spatial error);
    // the standard deviation improves from 2 to 4 points.
    for (std::size_t k = 0; k + 1 < 4; ++k) CHECK(rows[k + 1].errorMean < rows[k].errorMean);
    CHECK(rows[3].errorStd < rows[1].errorStd);
    // The centre node is shared by the odd levels: computed once.
    CHECK(rows[2].computed == 2);
  }
}

TEST_CASE("peristep sample: Test 3 collocation is more accurate than Monte Carlo at equal sample counts",
          "[host][sample]") {
  TempDir dir;
  writeText(dir / "t3.toml", sceneText("interface_crack_sampling.toml", {{"nx", "17"}, {"ny", "17"}}));
  const ProcessResult pcm = sample(dir.path(), {"t3.toml", "--rule", "tensor", "--levels", "2,3", "--out", "pcm.h5"});
  const ProcessResult mc = sample(dir.path(), {"t3.toml", "--rule", "mc", "--samples", "4,9", "--out", "mc.h5"});
  INFO("collocation:\n" << pcm.out << pcm.err << "\nMonte Carlo:\n" << mc.out << mc.err);
  REQUIRE(pcm.exitCode == 0);
  REQUIRE(mc.exitCode == 0);
  const auto a = readStudyCsv(dir / "pcm.csv"), b = readStudyCsv(dir / "mc.csv");
  REQUIRE(a.size() == 2);
  REQUIRE(b.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(a[k].samples == b[k].samples);
    CHECK(a[k].errorMean < b[k].errorMean);
    CHECK(a[k].errorStd < b[k].errorStd);
  }
}

TEST_CASE("peristep sample: a Smolyak level-1 grid in 2 coordinates has 5 nodes and weights summing to 1",
          "[host][sample]") {
  TempDir dir;
  writeText(dir / "t2.toml", sceneText("composite_sampling.toml", {{"nx", "9"}, {"ny", "9"}}));
  const ProcessResult r = sample(dir.path(), {"t2.toml", "--rule", "smolyak", "--level", "1", "--out", "s.h5"});
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  const hid_t f = openHdf5(dir / "s.h5");
  REQUIRE(f >= 0);
  const Dataset w = readDataset(f, "/level_1/weights"), nodes = readDataset(f, "/level_1/nodes");
  const Dataset mean = readDataset(f, "/level_1/mean/ux"), samples = readDataset(f, "/level_1/samples/ux");
  H5Fclose(f);
  REQUIRE(w.values.size() == 5);
  CHECK(std::accumulate(w.values.begin(), w.values.end(), 0.0) == Approx(1.0).margin(1e-14));
  CHECK(nodes.shape == std::vector<hsize_t>{5, 2});
  REQUIRE(samples.shape == std::vector<hsize_t>{5, 9, 9});
  // The stored mean is the weighted sum of the stored samples (000:(3.10)).
  for (std::size_t i = 0; i < 81; ++i) {
    double m = 0;
    for (std::size_t k = 0; k < 5; ++k) m += w.values[k] * samples.values[k * 81 + i];
    CHECK(mean.values[i] == Approx(m).margin(1e-14));
  }
}

TEST_CASE("peristep sample: a loop killed part-way recomputes no finished sample and gives the same statistics",
          "[host][sample]") {
  TempDir dir;
  writeText(dir / "t1.toml", sceneText("smooth_sampling.toml", {{"nx", "17"}, {"ny", "17"}}));
  const std::vector<std::string> args{PERISTEP_HOST_BINARY, "sample", "t1.toml", "--rule", "tensor", "--level", "16",
                                      "--out", "study.h5", "--fmu", PERISTEP_FMU};
  const auto finished = [&] {
    std::size_t n = 0;
    if (fs::exists(dir / "study.samples"))
      for (const auto& e : fs::directory_iterator(dir / "study.samples")) n += e.path().extension() == ".bin";
    return n;
  };
  std::optional<ScopedEnv> tmp(std::in_place, "TMPDIR", privateTmp(dir).string());
  const pid_t pid = fork();
  if (pid == 0) {
    const int devnull = open("/dev/null", O_WRONLY);
    if (devnull < 0 || dup2(devnull, 1) < 0 || dup2(devnull, 2) < 0 || chdir(dir.path().c_str()) != 0) _exit(127);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (finished() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::size_t done = finished();
  INFO("samples finished before the kill: " << done);
  REQUIRE(done >= 3);
  REQUIRE(done < 16);  // killed part-way (16 samples take several seconds)

  const auto leftBehind = std::distance(fs::directory_iterator(dir / "tmp"), {});
  CHECK(leftBehind == 1);  // the killed run's unpacked FMU
  const ProcessResult resumed = runProcess(args, dir.path());
  INFO(resumed.out << resumed.err);
  REQUIRE(resumed.exitCode == 0);
  CHECK(std::distance(fs::directory_iterator(dir / "tmp"), {}) == leftBehind);  // a run that ends removes its own
  tmp.reset();
    const auto rows = readStudyCsv(dir / "study.csv");
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].computed == static_cast<double>(16 - done));

  TempDir fresh;
  writeText(fresh / "t1.toml", readText(dir / "t1.toml"));
  REQUIRE(runProcess(args, fresh.path()).exitCode == 0);
  for (const std::string name : {"/level_16/mean/ux", "/level_16/std/uy", "/level_16/mean/errorL2"}) {
    const hid_t a = openHdf5(dir / "study.h5"), b = openHdf5(fresh / "study.h5");
    const Dataset x = readDataset(a, name), y = readDataset(b, name);
    H5Fclose(a);
    H5Fclose(b);
    REQUIRE(!x.values.empty());
    CHECK(x.values == y.values);
  }
}

TEST_CASE("peristep sample: rules that do not fit the scene or the command line are input errors", "[host][sample]") {
  TempDir dir;
  writeText(dir / "t1.toml", sceneText("smooth_sampling.toml", {{"nx", "9"}, {"ny", "9"}}));
  const ProcessResult unknown = sample(dir.path(), {"t1.toml", "--rule", "latin", "--level", "2"});
  CHECK(unknown.exitCode == 2);
  CHECK_THAT(unknown.err, Contains("unknown rule 'latin'"));
  const ProcessResult mixed = sample(dir.path(), {"t1.toml", "--rule", "mc", "--level", "2", "--samples", "4"});
  CHECK(mixed.exitCode == 2);
  CHECK_THAT(mixed.err, Contains("--rule mc takes --samples"));
  const ProcessResult missing = sample(dir.path(), {"t1.toml", "--rule", "smolyak"});
  CHECK(missing.exitCode == 2);
  CHECK_THAT(missing.err, Contains("needs --level"));

  writeText(dir / "gc.toml", "[parameters]\nscene = \"glassCeramic\"\n");
  const ProcessResult none = sample(dir.path(), {"gc.toml", "--rule", "tensor", "--level", "2"});
  CHECK(none.exitCode == 2);
  CHECK_THAT(none.err, Contains("no random coordinates"));
}

TEST_CASE("peristep sample: a sample the component refuses is recorded and the study goes on", "[host][sample]") {
  // An unpacked PeriStep FMU whose binary refuses fmi3DoStep when xi[0] > 0.5 (host_failing_component.cpp).
  TempDir dir;
  {
    const peristep::host::FmuArchive archive(PERISTEP_FMU);
    fs::copy(archive.root(), dir / "fmu", fs::copy_options::recursive);
  }
  fs::copy_file(PERISTEP_FAILING_COMPONENT, dir / "fmu" / "binaries" / "x86_64-linux" / "PeriStep.so",
                fs::copy_options::overwrite_existing);
  writeText(dir / "t1.toml", sceneText("smooth_sampling.toml", {{"nx", "9"}, {"ny", "9"}}));
  const auto run = [&](const std::vector<std::string>& args) {
    std::vector<std::string> all{PERISTEP_HOST_BINARY, "sample", "t1.toml", "--fmu", (dir / "fmu").string()};
    all.insert(all.end(), args.begin(), args.end());
    return runProcess(all, dir.path());
  };

  SECTION("a quadrature rule: no moments (its weights do not allow dropping a node)") {
    const ProcessResult r = run({"--rule", "tensor", "--level", "3", "--out", "q.h5"});  // nodes -1.73, 0, 1.73
    INFO(r.out << r.err);
    CHECK(r.exitCode == 1);  // the files are written, the exit code says a sample failed
    CHECK_THAT(r.out, Contains("level 3: 1 of 3 samples failed; no moments") &&
                          Contains("sample 3 of 3 (xi = [1.73205]): fmi3DoStep returned fmi3Error"));
    const std::string csv = readText(dir / "q.csv");
    INFO(csv);
    CHECK(csv.find("\n3,3,3,,,,,") != std::string::npos);  // level 3, 3 samples, 3 computed, no errors
    const hid_t f = openHdf5(dir / "q.h5");
    REQUIRE(f >= 0);
    const Dataset mean = readDataset(f, "/level_3/mean/ux");
    H5Fclose(f);
    CHECK(std::isnan(mean.values.at(0)));
    // Restarted: the failed sample is finished too (its message is stored), nothing is recomputed.
    const ProcessResult again = run({"--rule", "tensor", "--level", "3", "--out", "q.h5"});
    CHECK(again.exitCode == 1);
    CHECK(readText(dir / "q.csv").find("\n3,3,0,") != std::string::npos);
  }
  SECTION("Monte Carlo: the moments of the successful samples, with their count") {
    const ProcessResult r = run({"--rule", "mc", "--samples", "12", "--out", "mc.h5"});
    INFO(r.out << r.err);
    CHECK(r.exitCode == 1);
    const hid_t f = openHdf5(dir / "mc.h5");
    REQUIRE(f >= 0);
    const Dataset nodes = readDataset(f, "/level_12/nodes"), samples = readDataset(f, "/level_12/samples/errorL2");
    const Dataset mean = readDataset(f, "/level_12/mean/errorL2");
    H5Fclose(f);
    double sum = 0;
    std::size_t ok = 0;
    for (std::size_t k = 0; k < 12; ++k) {
      CHECK(std::isnan(samples.values[k]) == (nodes.values[k] > 0.5));
      if (nodes.values[k] <= 0.5) sum += samples.values[k], ++ok;
    }
    REQUIRE(ok > 0);
    REQUIRE(ok < 12);
    CHECK_THAT(r.out, Contains(std::to_string(12 - ok) + " of 12 samples failed; the moments are over the " +
                               std::to_string(ok) + " successful samples"));
    CHECK(mean.values.at(0) == Approx(sum / static_cast<double>(ok)).epsilon(1e-14));
  }
}

TEST_CASE("peristep sample: Monte Carlo over realizations of the 002 bar stores the n', K' statistics",
          "[host][sample][gamut]") {
  // scenes/gamut_bar.toml at 16 bonds: the cyclic protocol on realizations 0, 1, 2 (--seed 0: seed 0 + k).
  TempDir dir;
  writeText(dir / "bar.toml", sceneText("gamut_bar.toml", {{"gamutBonds", "16"}}));
  const ProcessResult r =
      sample(dir.path(), {"bar.toml", "--rule", "mc", "--samples", "3", "--seed", "0", "--out", "bar.h5"});
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);

  // The scene names n' and K' as its results: the plot is their two distributions.
  CHECK_THAT(r.out, Contains("wrote bar.png"));
  const Picture plot = readPng(dir / "bar.png");
  CHECK(plot.width == samplePlotWidth(2));
  CHECK(plot.height == samplePlotHeight(2));

  const hid_t f = openHdf5(dir / "bar.h5");
  REQUIRE(f >= 0);
  const Dataset seeds = readDataset(f, "/level_3/seeds");
  std::map<std::string, double> mean;
  std::map<std::string, std::vector<double>> samples;
  for (const std::string name : {"cyclicExponent", "cyclicCoefficient"}) {
    samples[name] = readDataset(f, "/level_3/samples/" + name).values;
    mean[name] = readDataset(f, "/level_3/mean/" + name).values.at(0);
  }
  H5Fclose(f);
  CHECK(seeds.values == std::vector<double>{0, 1, 2});

  // The CSV's row: mean, std and the standard errors of every scalar output, here n' and K'.
  std::istringstream csv(readText(dir / "bar.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  const auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::istringstream s(line);
    for (std::string c; std::getline(s, c, ',');) out.push_back(c);
    return out;
  };
  const std::vector<std::string> names = cells(header), values = cells(row);
  REQUIRE(names.size() == values.size());
  const auto column = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    REQUIRE(it != names.end());
    return std::stod(values[static_cast<std::size_t>(it - names.begin())]);
  };
  for (const std::string name : {"cyclicExponent", "cyclicCoefficient"}) {
    INFO(name);
    const std::vector<double>& v = samples[name];
    REQUIRE(v.size() == 3);
    for (double x : v) CHECK(x > 0);  // every sample finished the protocol
    const double average = (v[0] + v[1] + v[2]) / 3;
    CHECK(mean[name] == Approx(average).epsilon(1e-14));
    CHECK(column("mean_" + name) == Approx(average).epsilon(1e-9));  // printed with 10 digits
    CHECK(column("std_" + name) > 0);
    CHECK(column("seMean_" + name) > 0);
    CHECK(column("seStd_" + name) > 0);
  }
}
