#include "base/yaml_file.h"

#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "tests/input_error_of.h"

namespace acdplan {
namespace {

/// The message of the InputError `read` throws, "" if none.
template <typename Read>
std::string MessageOf(Read read) {
  return test::InputErrorOf(read);
}

TEST(YamlFile, SyntaxErrorsNameTheLine) {
  EXPECT_EQ(MessageOf([] {
              YamlFile::Parse("a: 1\nb: [1, 2\n", "w.yaml");
            }).rfind("w.yaml:3: YAML syntax error: ", 0),
            0u);
}

TEST(YamlFile, TheRootMustBeAMapping) {
  EXPECT_EQ(MessageOf([] { YamlFile::Parse("- 1\n- 2\n", "w.yaml"); }),
            "w.yaml: expected a mapping of keys, got a list");
  EXPECT_EQ(MessageOf([] { YamlFile::Parse("", "w.yaml"); }),
            "w.yaml: expected a mapping of keys, got nothing");
}

TEST(YamlFile, MissingFileUsesTheSharedWording) {
  EXPECT_EQ(MessageOf([] { YamlFile::Load("/nonexistent/w.yaml"); }),
            "/nonexistent/w.yaml: cannot read the file: No such file or directory");
}

TEST(YamlFile, ValuesAreCheckedWithTheirKeyPath) {
  const YamlFile f = YamlFile::Parse(
      "planner: {name: PRM, time_limit: fast, samples: 2.5}\n"
      "bounds: [0, 0, 1]\n"
      "list: [1, x]\n"
      "names: [a, [b]]\n",
      "s.yaml");
  const YAML::Node planner = f.root()["planner"];
  EXPECT_EQ(f.String(planner["name"], "planner.name"), "PRM");
  EXPECT_EQ(MessageOf([&] {
              f.CheckKeys(planner, "planner", {"name", "samples"});
            }),
            "s.yaml: planner.time_limit: unknown key (expected one of: name, samples)");
  EXPECT_EQ(MessageOf([&] {
              f.Number(planner["time_limit"], "planner.time_limit", "a positive number", Positive);
            }),
            "s.yaml: planner.time_limit: expected a positive number, got 'fast'");
  EXPECT_EQ(
      MessageOf([&] { f.Integer(planner["samples"], "planner.samples", "an integer >= 1", 1); }),
      "s.yaml: planner.samples: expected an integer >= 1, got '2.5'");
  EXPECT_EQ(
      MessageOf([&] { f.Numbers(f.root()["bounds"], "bounds", 4, "[xmin, ymin, xmax, ymax]"); }),
      "s.yaml: bounds: expected [xmin, ymin, xmax, ymax] (4 finite numbers), got a list");
  EXPECT_EQ(MessageOf([&] { f.Numbers(f.root()["list"], "list", "a list of numbers"); }),
            "s.yaml: list[1]: expected a finite number, got 'x'");
  EXPECT_EQ(MessageOf([&] { f.Strings(f.root()["names"], "names"); }),
            "s.yaml: names[1]: expected a string, got a list");
  EXPECT_EQ(MessageOf([&] { f.ExpectMap(f.root()["missing"], "missing"); }),
            "s.yaml: missing: expected a mapping of keys, got nothing");
  EXPECT_EQ(f.Numbers(f.root()["bounds"], "bounds", 3, "[a, b, c]"),
            (std::vector<double>{0, 0, 1}));
}

TEST(YamlFile, PathsResolveAgainstTheFilesFolder) {
  const YamlFile f = YamlFile::Parse("{}", "configs/bench/b.yaml");
  EXPECT_EQ(f.ResolvePath("../demo.yaml"), "configs/demo.yaml");
  EXPECT_EQ(f.ResolvePath("/abs/w.yaml"), "/abs/w.yaml");
  EXPECT_EQ(YamlFile::Child("", "a"), "a");
  EXPECT_EQ(YamlFile::Child("a", "b"), "a.b");
  EXPECT_EQ(YamlFile::Item("a.b", 3), "a.b[3]");
}

}  // namespace
}  // namespace acdplan
