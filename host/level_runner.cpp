#include "level_runner.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include "host_errors.hpp"
#include "simulation.hpp"

namespace peristep::host {

namespace {

// What the child sends back through the pipe, followed by its error message (if any).
struct ChildReport {
  bool ok = false;
  double lx = 0, errorL2 = 0, wallSeconds = 0;
};

ChildReport runInThisProcess(const FmuArchive& fmu, const ModelDescription& md, const Scene& scene,
                             const FmuInstance::Options& options, std::string& error) {
  ChildReport report;
  try {
    const auto start = std::chrono::steady_clock::now();
    FmuLibrary library(fmu.binaryFile(md.coSimulationIdentifier));
    Simulation simulation(library, md, scene, options);
    for (const Increment& inc : simulation.schedule()) {
      if (!simulation.mayContinue()) break;
      simulation.step(inc);
    }
    report.errorL2 = simulation.readScalar("errorL2");
    report.lx = simulation.readScalar("Lx");
    simulation.terminate();
    report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.ok = true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  return report;
}

void writeAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n <= 0) return;  // the parent reports a short message as a failed level
    p += n, size -= static_cast<std::size_t>(n);
  }
}

std::string readAll(int fd) {
  std::string data;
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    data.append(buffer, static_cast<std::size_t>(n));
  }
  return data;
}

}  // namespace

Scene sceneAtLevel(const Scene& scene, const ModelDescription& md, std::uint64_t level) {
  return sceneWithGrid(scene, md, level + 1, level + 1, "refine");
}

LevelResult runLevel(const FmuArchive& fmu, const ModelDescription& md, const Scene& scene, std::uint64_t level,
                     const FmuInstance::Options& options) {
  const Scene refined = sceneAtLevel(scene, md, level);
  int fds[2];
  if (pipe(fds) != 0) throw RunError("cannot create a pipe for level " + std::to_string(level));
  std::cout.flush();
  std::cerr.flush();  // nothing buffered may be written twice, once by each process
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]), close(fds[1]);
    throw RunError("cannot fork a process for level " + std::to_string(level));
  }
  if (child == 0) {
    close(fds[0]);
    std::string error;
    const ChildReport report = runInThisProcess(fmu, md, refined, options, error);
    writeAll(fds[1], &report, sizeof report);
    writeAll(fds[1], error.data(), error.size());
    close(fds[1]);
    // _exit: the parent's destructors (the unpacked FMU directory, open files) are not ours to run.
    _exit(report.ok ? 0 : 1);
  }
  close(fds[1]);
  const std::string data = readAll(fds[0]);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  while (wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }

  const std::string where = "level " + std::to_string(level) + " (nx = ny = " + std::to_string(level + 1) + ")";
  if (WIFSIGNALED(status))
    throw RunError(where + ": the process running it was killed by signal " + std::to_string(WTERMSIG(status)) +
                   " (" + strsignal(WTERMSIG(status)) + ")");
  ChildReport report;
  if (data.size() < sizeof report) throw RunError(where + ": the process running it ended without a report");
  std::memcpy(&report, data.data(), sizeof report);
  if (!report.ok) throw RunError(where + ": " + data.substr(sizeof report));

  LevelResult row;
  row.level = level;
  row.nx = row.ny = level + 1;
  row.h = report.lx / static_cast<double>(level);
  row.errorL2 = report.errorL2;
  row.wallSeconds = report.wallSeconds;
  row.peakRssMb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
  return row;
}

}  // namespace peristep::host
