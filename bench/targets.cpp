#include "bench/targets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/enum_names.h"
#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::bench {

namespace {

constexpr std::array<EnumName<Comparison>, 6> kComparisons = {{
    {Comparison::kLess, "<"},
    {Comparison::kLessEqual, "<="},
    {Comparison::kGreater, ">"},
    {Comparison::kGreaterEqual, ">="},
    {Comparison::kEqual, "=="},
    {Comparison::kNotEqual, "!="},
}};

std::string MetricName(const YamlFile& file, const YAML::Node& node, const std::string& key,
                       const TargetVocabulary& vocabulary) {
  const std::string name = file.String(node, key);
  if (vocabulary.check_metric) {
    const std::string rule = vocabulary.check_metric(name);
    if (!rule.empty()) file.Fail(key, rule);
  }
  return name;
}

/// Reads {metric, over, compare, value} of mapping `node` at `key`.
MetricTest ReadTest(const YamlFile& file, const YAML::Node& node, const std::string& key,
                    const TargetVocabulary& vocabulary) {
  auto child = [&](const char* name) { return YamlFile::Child(key, name); };
  MetricTest test;
  for (const char* required : {"metric", "compare", "value"}) {
    if (!node[required]) file.Fail(child(required), "required");
  }
  test.metric = MetricName(file, node["metric"], child("metric"), vocabulary);
  if (node["over"]) test.over = MetricName(file, node["over"], child("over"), vocabulary);
  test.compare = file.Parsed(node["compare"], child("compare"), ParseComparison);
  test.value = file.Number(node["value"], child("value"));
  return test;
}

/// Whether label text `have` is `want` (as numbers when both are numbers: "0.010" is "0.01").
bool SameLabel(const std::string& have, const std::string& want) {
  if (have == want) return true;
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double a = std::strtod(have.c_str(), &end_a);
  const double b = std::strtod(want.c_str(), &end_b);
  return !have.empty() && !want.empty() && *end_a == '\0' && *end_b == '\0' && a == b;
}

bool Applies(const Target& target, const TargetRow& row) {
  for (const auto& [label, values] : target.where) {
    auto it = row.labels.find(label);
    if (it == row.labels.end()) return false;
    if (std::none_of(values.begin(), values.end(),
                     [&](const std::string& v) { return SameLabel(it->second, v); })) {
      return false;
    }
  }
  return true;
}

/// The measured value of `test` on `row`; false if a metric is absent.
bool Measure(const MetricTest& test, const TargetRow& row, double* value) {
  auto m = row.metrics.find(test.metric);
  if (m == row.metrics.end()) return false;
  *value = m->second;
  if (!test.over.empty()) {
    auto o = row.metrics.find(test.over);
    if (o == row.metrics.end()) return false;
    // Not measured on either side: not measured (a ratio to a NaN time must not hold).
    if (std::isnan(m->second) || std::isnan(o->second)) {
      *value = std::nan("");
    } else {
      *value = o->second > 0 ? m->second / o->second : (m->second > 0 ? INFINITY : std::nan(""));
    }
  }
  return true;
}

std::string Shown(const MetricTest& test, double x) {
  if (std::isnan(x)) return "not measured";
  if (std::isinf(x)) return "∞";
  const size_t n = test.metric.size();
  if (!test.over.empty()) return FormatSignificant(x, 3) + "x";
  if (n > 5 && test.metric.compare(n - 5, 5, "_rate") == 0) {
    return FormatSignificant(100.0 * x, 4) + "%";
  }
  return FormatSignificant(x, 4);
}

}  // namespace

std::string ToString(Comparison comparison) { return NameOf(kComparisons, comparison); }

Comparison ParseComparison(const std::string& text) {
  return ValueOf(kComparisons, text, "comparison");
}

std::string MetricTest::Text() const {
  return metric + (over.empty() ? "" : " / " + over) + " " + ToString(compare) + " " +
         FormatSignificant(value, 6);
}

bool MetricTest::Holds(double x) const {
  if (std::isnan(x)) return false;
  switch (compare) {
    case Comparison::kLess:
      return x < value;
    case Comparison::kLessEqual:
      return x <= value;
    case Comparison::kGreater:
      return x > value;
    case Comparison::kGreaterEqual:
      return x >= value;
    case Comparison::kEqual:
      return x == value;
    case Comparison::kNotEqual:
      return x != value;
  }
  return false;
}

std::string Target::Label() const {
  if (!name.empty()) return name;
  std::string text = test.Text();
  for (const MetricTest& t : also) text += " and " + t.Text();
  for (size_t i = 0; i < any_of.size(); ++i) {
    text += (i == 0 ? " for one " : i + 1 == any_of.size() ? " and " : ", ") + any_of[i];
  }
  for (size_t i = 0; i < conditions.size(); ++i) {
    text += (i == 0 ? " where " : " and ") + conditions[i].Text();
  }
  return text;
}

std::vector<Target> ReadTargets(const YamlFile& file, const YAML::Node& node,
                                const std::string& key, const TargetVocabulary& vocabulary) {
  if (!node.IsSequence())
    file.Fail(key, "expected a list of targets, got " + YamlFile::Shown(node));
  std::vector<Target> targets;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string item = YamlFile::Item(key, i);
    const YAML::Node& t = node[i];
    file.CheckKeys(t, item,
                   {"name", "where", "if", "metric", "over", "compare", "value", "and", "any_of"});
    Target target;
    if (t["name"]) target.name = file.String(t["name"], YamlFile::Child(item, "name"));
    if (const YAML::Node& where = t["where"]) {
      const std::string wkey = YamlFile::Child(item, "where");
      if (!where.IsMap()) file.Fail(wkey, "expected a mapping, got " + YamlFile::Shown(where));
      for (const auto& entry : where) {
        // A key may be any YAML node; as<std::string>() would throw yaml-cpp's own exception.
        if (!entry.first.IsScalar()) {
          file.Fail(wkey, "expected a mapping with string keys, got " +
                              YamlFile::Shown(entry.first) + " as a key");
        }
        const std::string label = entry.first.Scalar();
        const std::string lkey = YamlFile::Child(wkey, label);
        if (std::find(vocabulary.labels.begin(), vocabulary.labels.end(), label) ==
            vocabulary.labels.end()) {
          file.Fail(lkey, UnknownName("label", label, vocabulary.labels));
        }
        std::vector<std::string> values =
            entry.second.IsSequence() ? file.Strings(entry.second, lkey)
                                      : std::vector<std::string>{file.String(entry.second, lkey)};
        if (values.empty()) file.Fail(lkey, "expected at least one value");
        target.where[label] = values;
      }
    }
    if (const YAML::Node& conditions = t["if"]) {
      const std::string ckey = YamlFile::Child(item, "if");
      if (!conditions.IsSequence()) {
        file.Fail(ckey, "expected a list of {metric, compare, value}, got " +
                            YamlFile::Shown(conditions));
      }
      for (size_t c = 0; c < conditions.size(); ++c) {
        const std::string ikey = YamlFile::Item(ckey, c);
        file.CheckKeys(conditions[c], ikey, {"metric", "over", "compare", "value"});
        target.conditions.push_back(ReadTest(file, conditions[c], ikey, vocabulary));
      }
    }
    if (const YAML::Node& also = t["and"]) {
      const std::string akey = YamlFile::Child(item, "and");
      if (!also.IsSequence()) {
        file.Fail(akey,
                  "expected a list of {metric, compare, value}, got " + YamlFile::Shown(also));
      }
      for (size_t c = 0; c < also.size(); ++c) {
        const std::string ikey = YamlFile::Item(akey, c);
        file.CheckKeys(also[c], ikey, {"metric", "over", "compare", "value"});
        target.also.push_back(ReadTest(file, also[c], ikey, vocabulary));
      }
    }
    if (t["any_of"]) {
      const std::string key_any = YamlFile::Child(item, "any_of");
      target.any_of = t["any_of"].IsSequence()
                          ? file.Strings(t["any_of"], key_any)
                          : std::vector<std::string>{file.String(t["any_of"], key_any)};
      if (target.any_of.empty()) file.Fail(key_any, "expected at least one label");
      for (const std::string& label : target.any_of) {
        if (std::find(vocabulary.labels.begin(), vocabulary.labels.end(), label) ==
            vocabulary.labels.end()) {
          file.Fail(key_any, UnknownName("label", label, vocabulary.labels));
        }
      }
    }
    target.test = ReadTest(file, t, item, vocabulary);
    targets.push_back(target);
  }
  return targets;
}

std::vector<Target> LoadTargetsFile(const std::string& path, const TargetVocabulary& vocabulary) {
  const YamlFile file = YamlFile::Load(path);
  file.CheckKeys(file.root(), "", {"targets"});
  if (!file.root()["targets"]) file.Fail("targets", "required");
  return ReadTargets(file, file.root()["targets"], "targets", vocabulary);
}

std::string TargetsToJson(const std::vector<Target>& targets) {
  auto test_json = [](const MetricTest& test) {
    nlohmann::ordered_json j;
    j["metric"] = test.metric;
    if (!test.over.empty()) j["over"] = test.over;
    j["compare"] = ToString(test.compare);
    j["value"] = test.value;
    return j;
  };
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Target& t : targets) {
    nlohmann::ordered_json j;
    if (!t.name.empty()) j["name"] = t.name;
    if (!t.where.empty()) j["where"] = t.where;
    if (!t.conditions.empty()) {
      j["if"] = nlohmann::ordered_json::array();
      for (const MetricTest& c : t.conditions) j["if"].push_back(test_json(c));
    }
    const nlohmann::ordered_json test = test_json(t.test);
    for (const auto& [k, v] : test.items()) j[k] = v;
    if (!t.also.empty()) {
      j["and"] = nlohmann::ordered_json::array();
      for (const MetricTest& a : t.also) j["and"].push_back(test_json(a));
    }
    // One label as a string, as it is usually written.
    if (t.any_of.size() == 1) j["any_of"] = t.any_of[0];
    if (t.any_of.size() > 1) j["any_of"] = t.any_of;
    list.push_back(j);
  }
  return list.dump();
}

std::vector<TargetCheck> CheckTargets(const std::vector<Target>& targets,
                                      const std::vector<TargetRow>& rows) {
  std::vector<TargetCheck> checks;
  for (const Target& target : targets) {
    std::vector<TargetCheck> row_checks;
    for (const TargetRow& row : rows) {
      if (!Applies(target, row)) continue;
      bool applies = true;
      for (const MetricTest& condition : target.conditions) {
        double x = 0.0;
        if (!Measure(condition, row, &x) || !condition.Holds(x)) applies = false;
      }
      TargetCheck check;
      if (!applies || !Measure(target.test, row, &check.measured)) continue;
      check.target = &target;
      check.row = &row;
      check.holds = target.test.Holds(check.measured);
      for (const MetricTest& also : target.also) {
        double x = std::nan("");
        const bool present = Measure(also, row, &x);
        if (present && also.Holds(x)) continue;
        check.holds = false;
        if (!check.missed_also.empty()) check.missed_also += "; ";
        check.missed_also += also.metric + (also.over.empty() ? "" : " / " + also.over) + " " +
                             (present ? Shown(also, x) : "absent");
      }
      row_checks.push_back(check);
    }
    if (target.any_of.empty()) {
      checks.insert(checks.end(), row_checks.begin(), row_checks.end());
      continue;
    }
    // Groups: the rows' labels without the `any_of` ones, in the order of their first rows.
    std::vector<std::map<std::string, std::string>> keys;
    std::vector<TargetCheck> groups;
    for (const TargetCheck& check : row_checks) {
      std::map<std::string, std::string> key = check.row->labels;
      for (const std::string& label : target.any_of) key.erase(label);
      const auto it = std::find(keys.begin(), keys.end(), key);
      if (it == keys.end()) {
        keys.push_back(key);
        groups.push_back(check);
      } else {
        TargetCheck& group = groups[static_cast<size_t>(it - keys.begin())];
        if (!group.holds && check.holds) group = check;
      }
    }
    checks.insert(checks.end(), groups.begin(), groups.end());
  }
  return checks;
}

std::string TargetChecksMarkdown(const std::vector<TargetCheck>& checks,
                                 const std::vector<std::string>& columns) {
  std::ostringstream md;
  md << "|";
  for (const std::string& c : columns) md << " " << c << " |";
  md << " target | measured | |\n|";
  for (size_t i = 0; i < columns.size() + 3; ++i) md << "---|";
  md << "\n";
  int holds = 0, missed = 0;
  for (const TargetCheck& check : checks) {
    (check.holds ? holds : missed)++;
    md << "|";
    for (const std::string& c : columns) {
      auto it = check.row->labels.find(c);
      md << " " << (it == check.row->labels.end() ? "—" : it->second) << " |";
    }
    md << " " << check.target->Label() << " | " << Shown(check.target->test, check.measured)
       << (check.missed_also.empty() ? "" : " (but " + check.missed_also + ")") << " | "
       << (check.holds ? "holds" : "**missed**") << " |\n";
  }
  md << "\n" << holds << " target checks hold, " << missed << " missed.\n";
  return md.str();
}

}  // namespace acdplan::bench
