#include "bench/record.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "base/enum_names.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"
#include "bench/summary.h"

namespace acdplan::bench {

namespace {

constexpr std::array<EnumName<RunStatus>, 4> kRunStatuses = {{
    {RunStatus::kSolved, "solved"},
    {RunStatus::kUnsolved, "unsolved"},
    {RunStatus::kCrashed, "crashed"},
    {RunStatus::kTimeout, "timeout"},
}};

}  // namespace

std::string ToString(RunStatus status) { return NameOf(kRunStatuses, status); }

RunStatus ParseRunStatus(const std::string& text) {
  return ValueOf(kRunStatuses, text, "run status");
}

namespace {

const std::vector<std::string> kCaseColumns = {
    "world",   "family",  "passage_width", "workspace_width", "robot",
    "sampler", "planner", "budget",        "time_limit",      "sample_budget"};

/// runs.csv: "case", the case's columns, then the run's.
const std::vector<std::string> kColumns = [] {
  std::vector<std::string> columns = {"case"};
  columns.insert(columns.end(), kCaseColumns.begin(), kCaseColumns.end());
  for (const char* c : {"run", "seed", "status", "solved", "time_s", "decomposition_s", "samples",
                        "collision_checks", "path_length", "components", "openings"}) {
    columns.push_back(c);
  }
  return columns;
}();
const size_t kColumnCount = kColumns.size();

/// 17 significant digits: a read gives back the same double.
std::string Real(double x) { return FormatSignificant(x, 17); }

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

long long Integer(const std::vector<std::string>& f, size_t i, size_t* column) {
  *column = i;
  size_t used = 0;
  const long long v = std::stoll(f[i], &used);
  if (used != f[i].size()) throw std::invalid_argument("trailing");
  return v;
}

double RealField(const std::vector<std::string>& f, size_t i, size_t* column) {
  *column = i;
  size_t used = 0;
  const double v = std::stod(f[i], &used);
  if (used != f[i].size()) throw std::invalid_argument("trailing");
  return v;
}

}  // namespace

const std::vector<std::string>& CaseCsvColumns() { return kCaseColumns; }

std::string CaseCsvFields(const CaseDescription& c) {
  std::ostringstream out;
  out << c.world << "," << c.family << "," << Real(c.passage_width) << ","
      << Real(c.workspace_width) << "," << c.robot << "," << c.sampler << "," << c.planner << ","
      << c.budget << "," << Real(c.time_limit) << "," << c.sample_budget;
  return out.str();
}

CaseDescription ReadCaseCsvFields(const std::vector<std::string>& f, size_t first, size_t* column) {
  if (f.size() < first + kCaseColumns.size()) {
    *column = f.size() > 0 ? f.size() - 1 : 0;
    throw std::invalid_argument("too few fields");
  }
  CaseDescription c;
  c.world = f[first];
  c.family = f[first + 1];
  c.passage_width = RealField(f, first + 2, column);
  c.workspace_width = RealField(f, first + 3, column);
  c.robot = f[first + 4];
  c.sampler = f[first + 5];
  c.planner = f[first + 6];
  c.budget = f[first + 7];
  c.time_limit = RealField(f, first + 8, column);
  c.sample_budget = static_cast<int>(Integer(f, first + 9, column));
  return c;
}

void AddCaseJson(const CaseDescription& c, nlohmann::json* object) {
  nlohmann::json& e = *object;
  e["world"] = c.world;
  e["family"] = c.family;
  e["passage_width"] = c.passage_width;
  e["workspace_width"] = c.workspace_width;
  e["robot"] = c.robot;
  e["sampler"] = c.sampler;
  e["planner"] = c.planner;
  e["budget"] = c.budget;
}

std::string BenchCsvHeader() {
  std::string header;
  for (const std::string& c : kColumns) header += (header.empty() ? "" : ",") + c;
  return header;
}

std::string BenchRecordsToCsv(const std::vector<BenchRecord>& records) {
  std::ostringstream out;
  out << BenchCsvHeader() << "\n";
  for (const BenchRecord& r : records) {
    out << r.case_index << "," << CaseCsvFields(r.what) << "," << r.run << "," << r.seed << ","
        << ToString(r.status) << "," << (r.solved ? 1 : 0) << "," << Real(r.time_s) << ","
        << Real(r.decomposition_s) << "," << r.samples << "," << r.collision_checks << ","
        << Real(r.path_length) << "," << r.components << "," << r.openings << "\n";
  }
  return out.str();
}

std::vector<BenchRecord> ReadBenchRecordsCsv(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string line;
  if (!std::getline(in, line) || line != BenchCsvHeader()) {
    throw InputError(path + ":1: expected the header " + BenchCsvHeader());
  }
  std::vector<BenchRecord> records;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const std::vector<std::string> f = Split(line);
    const std::string where = path + ":" + std::to_string(number);
    if (f.size() != kColumnCount) {
      throw InputError(where + ": expected " + std::to_string(kColumnCount) + " fields, got " +
                       std::to_string(f.size()));
    }
    size_t column = 0;
    try {
      BenchRecord r;
      auto integer = [&](size_t i) { return Integer(f, i, &column); };
      auto unsigned_integer = [&](size_t i) {
        column = i;
        size_t used = 0;
        if (!f[i].empty() && f[i][0] == '-') throw std::invalid_argument("negative");
        const unsigned long long v = std::stoull(f[i], &used);
        if (used != f[i].size()) throw std::invalid_argument("trailing");
        return static_cast<std::uint64_t>(v);
      };
      auto real = [&](size_t i) { return RealField(f, i, &column); };
      r.case_index = static_cast<int>(integer(0));
      r.what = ReadCaseCsvFields(f, 1, &column);
      r.run = static_cast<int>(integer(11));
      r.seed = unsigned_integer(12);
      column = 13;
      r.status = ParseRunStatus(f[13]);
      r.solved = integer(14) != 0;
      r.time_s = real(15);
      r.decomposition_s = real(16);
      r.samples = unsigned_integer(17);
      r.collision_checks = unsigned_integer(18);
      r.path_length = real(19);
      r.components = static_cast<int>(integer(20));
      r.openings = static_cast<int>(integer(21));
      records.push_back(r);
    } catch (const std::exception&) {
      throw InputError(where + ": column " + kColumns[column] + ": cannot read '" + f[column] +
                       "'");
    }
  }
  return records;
}

void SortBenchRecords(std::vector<BenchRecord>* records) {
  std::stable_sort(records->begin(), records->end(),
                   [](const BenchRecord& a, const BenchRecord& b) {
                     return std::tie(a.case_index, a.run) < std::tie(b.case_index, b.run);
                   });
}

std::string BenchManifestToJson(const BenchManifest& m) {
  nlohmann::json j;
  j["format"] = "acdplan.bench/1";
  j["name"] = m.name;
  j["description"] = m.description;
  j["spec"] = m.spec;
  j["seed"] = m.seed;
  j["runs"] = m.runs;
  j["cases"] = m.cases;
  j["shards"] = m.shards;
  j["planned_runs"] = m.planned_runs;
  j["interrupted"] = m.interrupted;
  j["hostname"] = m.hostname;
  j["cpus"] = m.cpus;
  j["load_average"] = m.load_average;
  j["jobs"] = m.jobs;
  j["started"] = m.started;
  j["wall_s"] = m.wall_s;
  if (!m.targets.empty()) j["targets"] = nlohmann::json::parse(TargetsToJson(m.targets));
  return j.dump(2) + "\n";
}

BenchManifest ReadBenchManifest(const std::string& path) {
  const std::string text = ReadFile(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path + ": not valid JSON: " + error.what());
  }
  if (!j.is_object() || j.value("format", "") != "acdplan.bench/1") {
    throw InputError(path + ": format: expected \"acdplan.bench/1\"");
  }
  BenchManifest m;
  const char* key = "";
  try {
    key = "name", m.name = j.at("name").get<std::string>();
    key = "description", m.description = j.at("description").get<std::string>();
    key = "spec", m.spec = j.at("spec").get<std::string>();
    key = "seed", m.seed = j.at("seed").get<std::uint64_t>();
    key = "runs", m.runs = j.at("runs").get<int>();
    key = "cases", m.cases = j.at("cases").get<int>();
    key = "shards", m.shards = j.at("shards").get<std::vector<std::string>>();
    key = "planned_runs", m.planned_runs = j.at("planned_runs").get<std::uint64_t>();
    key = "interrupted", m.interrupted = j.at("interrupted").get<bool>();
    key = "hostname", m.hostname = j.at("hostname").get<std::string>();
    key = "cpus", m.cpus = j.at("cpus").get<int>();
    key = "load_average", m.load_average = j.at("load_average").get<double>();
    key = "jobs", m.jobs = j.at("jobs").get<int>();
    key = "started", m.started = j.at("started").get<std::string>();
    key = "wall_s", m.wall_s = j.at("wall_s").get<double>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(path + ": " + key + ": missing or of the wrong type");
  }
  if (j.contains("targets")) {  // JSON is YAML: the benchmark file's reader checks them.
    const YamlFile file = YamlFile::Parse(nlohmann::json{{"targets", j["targets"]}}.dump(), path);
    m.targets = ReadTargets(file, file.root()["targets"], "targets", PlanningTargetVocabulary());
  }
  return m;
}

}  // namespace acdplan::bench
