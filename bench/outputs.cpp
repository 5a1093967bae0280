#include "bench/outputs.h"

#include <algorithm>
#include <filesystem>

#include "base/file_io.h"
#include "bench/ompl_log.h"
#include "bench/stats.h"
#include "bench/summary.h"

namespace acdplan::bench {

void WriteBenchRecord(const std::string& dir, const BenchManifest& manifest,
                      std::vector<BenchRecord> records) {
  std::filesystem::create_directories(dir);
  SortBenchRecords(&records);
  const std::filesystem::path d(dir);
  WriteFileAtomically((d / "runs.csv").string(), BenchRecordsToCsv(records));
  WriteFileAtomically((d / "bench.json").string(), BenchManifestToJson(manifest));
}

void WriteBenchOutputs(const std::string& dir, const BenchManifest& manifest,
                       std::vector<BenchRecord> records) {
  SortBenchRecords(&records);
  WriteBenchRecord(dir, manifest, records);
  const std::filesystem::path d(dir);
  const std::vector<BenchCaseSummary> cases = SummarizeBenchCases(records);
  WriteFileAtomically((d / "results.json").string(), BenchResultsJson(manifest, cases));
  WriteFileAtomically((d / "summary.md").string(), BenchSummaryMarkdown(manifest, cases));
  std::vector<std::string> worlds;
  for (const BenchRecord& r : records) {
    if (std::find(worlds.begin(), worlds.end(), r.what.world) == worlds.end()) {
      worlds.push_back(r.what.world);
    }
  }
  for (const std::string& world : worlds) {
    WriteFileAtomically((d / BenchOmplLogName(world)).string(),
                        BenchOmplLog(manifest, records, world));
  }
  // Logs of worlds this run does not have (an earlier run into the same folder) would be
  // mistaken for its results.
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(d, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ompl_", 0) != 0 || entry.path().extension() != ".log") continue;
    const bool current = std::any_of(worlds.begin(), worlds.end(), [&](const std::string& w) {
      return BenchOmplLogName(w) == name;
    });
    if (!current) std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace acdplan::bench
