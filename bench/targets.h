#pragma once
// Acceptance targets of a benchmark, read from its YAML (`targets:`) and checked on its
// measured rows. The targets live in the benchmark's files, never in code: each benchmark
// only says which rows it has, which labels they carry and which metrics they measure.
//
// A target, in YAML (every key but `metric`, `compare` and `value` is optional):
//
//   targets:
//     - name: "acd where uniform fails"    # shown in the report (default: the test itself)
//       where: {planner: PRM, sampler: [acd, uniform]}   # rows whose labels match (a value
//                                          # or a list of values; numbers compare as numbers)
//       if:                                # preconditions on the row; a row failing one is
//         - {metric: uniform.success_rate, compare: "<=", value: 0.2}   # not checked
//       metric: acd.success_rate           # what is measured (the benchmark's names)
//       over: uniform.success_rate         # optional divisor: the test is on metric / over
//       compare: ">="                      # one of <, <=, >, >=, ==, !=
//       value: 0.95                        # the threshold
//       and:                               # optional further tests that must hold on the
//         - {metric: parts, over: vhacd.parts, compare: "<=", value: 1}   # same row
//       any_of: tau_rel                    # optional: rows that differ only in this label
//                                          # (or these labels: [tau_rel, max_hulls]) make one
//                                          # check, which holds if one of them does
//
// Each row the target applies to gives one check: "holds" or "missed". A metric the row does
// not have makes the target not apply to it; a metric the row has but could not measure
// (NaN, e.g. a median time without a solved run) misses.

#include <map>
#include <string>
#include <vector>

#include "base/yaml_file.h"

namespace acdplan::bench {

/// A comparison of a measured value with a threshold.
enum class Comparison { kLess, kLessEqual, kGreater, kGreaterEqual, kEqual, kNotEqual };

/// "<", "<=", ">", ">=", "==", "!=".
std::string ToString(Comparison comparison);

/// Inverse of ToString().
/// @throws InputError "unknown comparison '<text>' (expected one of: <, <=, >, >=, ==, !=)".
Comparison ParseComparison(const std::string& text);

/// `metric [/ over] compare value`.
struct MetricTest {
  std::string metric;  ///< A metric name of the benchmark's rows.
  std::string over;    ///< A divisor metric, or "" for none.
  Comparison compare = Comparison::kGreaterEqual;
  double value = 0.0;
  /// "acd.success_rate >= 0.95" or "uniform.median_time_s / acd.median_time_s >= 10".
  std::string Text() const;
  /// Whether `measured` passes (false for NaN).
  bool Holds(double measured) const;
};

/// One acceptance target.
struct Target {
  std::string name;                                       ///< Label ("" : the test's text).
  std::map<std::string, std::vector<std::string>> where;  ///< Label -> accepted values.
  std::vector<MetricTest> conditions;                     ///< `if:`, all must hold.
  MetricTest test;
  std::vector<MetricTest> also;  ///< `and:`, must hold on the same row as `test`.
  /// `any_of:` a label, or a list of labels: the rows that differ only in them form one
  /// check, which holds if the tests hold on one of them ("one setting meets all"); empty: one
  /// check per row.
  std::vector<std::string> any_of;
  /// `name`, or the test's text when it has none.
  std::string Label() const;
};

/// What a benchmark's rows offer to targets: the labels `where` may filter on, and a check of
/// a metric name (returns "" if the name is known, else the rule broken, e.g. "unknown metric
/// 'x' (expected one of: ...)").
struct TargetVocabulary {
  std::vector<std::string> labels;
  std::string (*check_metric)(const std::string& metric) = nullptr;
};

/// Reads the `targets:` list at `node` (key path `key`, e.g. "targets") of `file`.
/// @throws InputError "<file>: <key path>: <rule>", e.g. "b.yaml: targets[1].compare:
///         unknown comparison '=>' (expected one of: <, <=, >, >=, ==, !=)", for unknown keys,
///         missing or malformed fields, unknown labels or metrics.
std::vector<Target> ReadTargets(const YamlFile& file, const YAML::Node& node,
                                const std::string& key, const TargetVocabulary& vocabulary);

/// Loads a targets file: a mapping with one key, `targets:`.
/// @throws InputError as ReadTargets(), and "<file>: cannot read the file" or a YAML
///         syntax error with its line.
std::vector<Target> LoadTargetsFile(const std::string& path, const TargetVocabulary& vocabulary);

/// The targets as JSON text (a list; the YAML keys), which ReadTargets() reads back (JSON is
/// YAML): a benchmark's output folder keeps its targets so a merge can check them.
std::string TargetsToJson(const std::vector<Target>& targets);

/// One row of a benchmark as targets see it.
struct TargetRow {
  std::map<std::string, std::string> labels;  ///< E.g. world, robot, planner, budget.
  std::map<std::string, double> metrics;      ///< Absent: not applicable; NaN: not measured.
};

/// One target checked on one row.
struct TargetCheck {
  const Target* target = nullptr;
  const TargetRow* row = nullptr;
  double measured = 0.0;  ///< metric, or metric / over.
  bool holds = false;
  /// The `and:` tests that missed on `row`, with their values ("" when none did).
  std::string missed_also;
};

/// Every target on every row it applies to (where matches, conditions hold, metrics present),
/// target-major, rows in the given order; with `any_of`, one check per group of such rows (in
/// the order of their first rows), pointing at the first row that holds, else at the group's
/// first row. The checks point into `targets` and `rows`, which
/// must outlive them.
std::vector<TargetCheck> CheckTargets(const std::vector<Target>& targets,
                                      const std::vector<TargetRow>& rows);

/// A Markdown table of `checks`: one column per label in `columns`, then target, measured and
/// "holds" / "**missed**", and a line "N target checks hold, M missed." Rates (metric names
/// ending in "_rate") without a divisor are shown as percentages, ratios with an "x".
std::string TargetChecksMarkdown(const std::vector<TargetCheck>& checks,
                                 const std::vector<std::string>& columns);

}  // namespace acdplan::bench
