#pragma once
// What every fuzz target shares: the input as text, and as a file for readers that take a path.
#include <cstddef>
#include <cstdint>
#include <string>

namespace acdplan::fuzz {

/// The fuzz input as a string (bytes as they are, NULs included).
std::string InputText(const std::uint8_t* data, std::size_t size);

/// Writes `text` to the file `name` in this process's temporary folder and returns its path.
/// The folder is made on the first call (mkdtemp under $TMPDIR, else /tmp) and removed at
/// exit; the same `name` gives the same path on every call, so a fuzzing run reuses one file
/// per name instead of leaving one per input.
std::string WriteInputFile(const std::string& name, const std::string& text);

}  // namespace acdplan::fuzz
