// Writes the default instance of every generator (envs/generators.h) as envs/2d/<name>.yaml.
// Usage: acdplan_generate_envs OUTPUT_FOLDER   (the committed files use seed 1)

#include <filesystem>
#include <iostream>

#include "base/input_error.h"
#include "envs/generators.h"
#include "envs/workspace_yaml.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: acdplan_generate_envs OUTPUT_FOLDER\n";
    return 2;
  }
  constexpr std::uint64_t kSeed = 1;
  try {
    for (const std::string& name : acdplan::envs::GeneratorNames()) {
      const std::filesystem::path path = std::filesystem::path(argv[1]) / (name + ".yaml");
      acdplan::envs::WriteWorkspace2dYaml(acdplan::envs::GenerateWorkspace2d(name, kSeed),
                                          path.string());
      std::cout << path.string() << "\n";
    }
  } catch (const acdplan::InputError& error) {
    std::cerr << "acdplan_generate_envs: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
