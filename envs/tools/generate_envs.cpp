// Writes the default instance of every generator (envs/generators.h) as envs/2d/<name>.yaml,
// and of every 3D generator (envs/generators3d.h) as envs/3d/<name>.yaml with its obstacles
// as envs/3d/<name>_<k>.obj.
// Usage: acdplan_generate_envs OUTPUT_FOLDER [OUTPUT_FOLDER_3D]   (the committed files use
// seed 1; without the second folder only the 2D worlds are written)

#include <filesystem>
#include <iostream>

#include "base/input_error.h"
#include "envs/generators.h"
#include "envs/generators3d.h"
#include "envs/workspace_yaml.h"

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::cerr << "usage: acdplan_generate_envs OUTPUT_FOLDER [OUTPUT_FOLDER_3D]\n";
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
    for (int i = 0; argc == 3 && i < static_cast<int>(acdplan::envs::Generator3dNames().size());
         ++i) {
      const std::string name = acdplan::envs::Generator3dNames()[i];
      const std::filesystem::path path = std::filesystem::path(argv[2]) / (name + ".yaml");
      acdplan::envs::WriteWorkspace3dYaml(acdplan::envs::GenerateWorkspace3d(name, kSeed),
                                          path.string());
      std::cout << path.string() << "\n";
    }
  } catch (const acdplan::InputError& error) {
    std::cerr << "acdplan_generate_envs: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
