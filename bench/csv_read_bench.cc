// Benchmark of the trial-log reader: a 1,000,000-row surge log (t, force, position at a third
// of the rows, velocity at two thirds, as sensors at different rates give) is written to a
// temporary directory, then read three times. Reports the best time and the growth of the
// peak resident memory during a read, against the file size.
// Targets (docs/formats.md): under 1 s, and under 3× the file size in memory.
// Exit status 1 when a target is missed.
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "uuvplan/io/io.h"

namespace {

constexpr int kRows = 1000000;
constexpr double kMiB = 1024.0 * 1024.0;

// Written row by row so that making the file costs no memory worth measuring.
void WriteLog(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fprintf(f, "# csv_read_bench: surge trial, 100 Hz\nt,force_surge,pos_surge,vel_surge\n");
  for (int i = 0; i < kRows; ++i) {
    const double t = i * 0.01;
    const double force = 100.0 * std::sin(0.05 * t);
    const double vel = 0.4 * std::sin(0.05 * t - 0.3);
    const double pos = -8.0 * std::cos(0.05 * t - 0.3);
    if (i % 3 == 0) {
      std::fprintf(f, "%.2f,%.6g,%.7g,\n", t, force, pos);
    } else {
      std::fprintf(f, "%.2f,%.6g,,%.6g\n", t, force, vel);
    }
  }
  std::fclose(f);
}

// A field of /proc/self/status in kB (VmRSS: resident now, VmHWM: peak resident).
long StatusKb(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  }
  return -1;
}

// Sets VmHWM back to the current resident size (Linux >= 4.0); false where not allowed.
bool ResetPeak() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

}  // namespace

int main() {
  std::string pattern = (std::filesystem::temp_directory_path() / "csv_read_bench_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    std::perror("mkdtemp");
    return 2;
  }
  const std::filesystem::path dir(pattern);
  const std::string path = (dir / "surge.csv").string();
  WriteLog(path);
  const double file_mb = std::filesystem::file_size(path) / kMiB;

  double best_s = 1e9;
  double peak_mb = 0.0;
  std::size_t rows = 0;
  for (int run = 0; run < 3; ++run) {
    // Without a reset the first run is still right: making the file held little memory.
    if (!ResetPeak() && run > 0) continue;
    const long rss_before = StatusKb("VmRSS");
    const auto start = std::chrono::steady_clock::now();
    const uuvplan::model::TrialLog log = uuvplan::io::ReadTrialLog(path);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    best_s = std::min(best_s, elapsed.count());
    peak_mb = std::max(peak_mb, (StatusKb("VmHWM") - rss_before) / 1024.0);
    rows = log.size();
  }
  std::filesystem::remove_all(dir);

  const double ratio = peak_mb / file_mb;
  std::printf("csv_read: rows=%zu file_MB=%.1f seconds=%.3f peak_MB=%.1f ratio=%.2f\n", rows,
              file_mb, best_s, peak_mb, ratio);
  const bool met = rows == static_cast<std::size_t>(kRows) && best_s < 1.0 && ratio < 3.0;
  if (!met) std::printf("csv_read: target missed (< 1 s and < 3x the file size)\n");
  return met ? 0 : 1;
}
