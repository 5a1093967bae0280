#include "bench/merge.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>

#include "base/input_error.h"

namespace acdplan::bench {

void MergeBenchRecords(const std::vector<std::string>& dirs, BenchManifest* manifest,
                       std::vector<BenchRecord>* records) {
  if (dirs.empty()) throw InputError("bench-merge: expected at least one folder");
  std::map<std::pair<int, int>, std::string> seen;
  records->clear();
  for (size_t i = 0; i < dirs.size(); ++i) {
    const std::filesystem::path d(dirs[i]);
    const std::string manifest_path = (d / "bench.json").string();
    const std::string runs_path = (d / "runs.csv").string();
    const BenchManifest m = ReadBenchManifest(manifest_path);
    if (i == 0) {
      *manifest = m;
    } else {
      auto differ = [&](const std::string& what, const std::string& a, const std::string& b) {
        throw InputError(manifest_path + ": " + what + ": '" + b + "' differs from '" + a +
                         "' in " + (std::filesystem::path(dirs[0]) / "bench.json").string());
      };
      if (m.name != manifest->name) differ("name", manifest->name, m.name);
      if (m.seed != manifest->seed) {
        differ("seed", std::to_string(manifest->seed), std::to_string(m.seed));
      }
      if (m.runs != manifest->runs) {
        differ("runs", std::to_string(manifest->runs), std::to_string(m.runs));
      }
      if (m.cases != manifest->cases) {
        differ("cases", std::to_string(manifest->cases), std::to_string(m.cases));
      }
      for (const std::string& s : m.shards) manifest->shards.push_back(s);
      manifest->planned_runs += m.planned_runs;
      manifest->interrupted = manifest->interrupted || m.interrupted;
      if (("," + manifest->hostname + ",").find("," + m.hostname + ",") == std::string::npos) {
        manifest->hostname += "," + m.hostname;
      }
      manifest->cpus = std::max(manifest->cpus, m.cpus);
      manifest->jobs = std::max(manifest->jobs, m.jobs);
      if (m.started < manifest->started) {
        manifest->started = m.started;
        manifest->load_average = m.load_average;
      }
      manifest->wall_s += m.wall_s;
    }
    for (const BenchRecord& r : ReadBenchRecordsCsv(runs_path)) {
      const auto key = std::make_pair(r.case_index, r.run);
      auto it = seen.find(key);
      if (it != seen.end()) {
        throw InputError(runs_path + ": run " + std::to_string(r.run) + " of case " +
                         std::to_string(r.case_index) + " (" + r.what.world + "/" + r.what.robot +
                         "/" + r.what.sampler + "/" + r.what.planner + "/" + r.what.budget +
                         ") is also in " + it->second);
      }
      seen.emplace(key, runs_path);
      records->push_back(r);
    }
  }
  std::sort(manifest->shards.begin(), manifest->shards.end());
  SortBenchRecords(records);
}

}  // namespace acdplan::bench
