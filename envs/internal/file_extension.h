#pragma once
// How the loaders tell files apart: by extension, in any case.

#include <filesystem>
#include <string>

#include "acd/internal/text_parsing.h"

namespace acdplan::envs::internal {

/// The extension of `path` with its dot, lower-cased (".obj"); empty if it has none.
inline std::string LowerExtension(const std::string& path) {
  return acd::internal::ToLower(std::filesystem::path(path).extension().string());
}

}  // namespace acdplan::envs::internal
