#pragma once
// Reading input files and writing output files, with one wording for their errors.

#include <fstream>
#include <istream>
#include <string>

namespace acdplan {

/// The whole of the file at `path`, bytes as they are.
/// @throws InputError "<path>: cannot read the file: <reason>", where the reason is the
///         system's ("No such file or directory") or "it is a directory".
std::string ReadFile(const std::string& path);

/// The file at `path` opened for reading bytes as they are, for readers that take a stream.
/// @throws InputError as ReadFile().
std::ifstream OpenFile(const std::string& path);

/// @throws InputError "PATH: cannot read the file: read error" if reading `in` (OpenFile(path))
///         failed.
void CheckRead(const std::istream& in, const std::string& path);

/// The rest of `in`, bytes as they are: in one piece where the stream tells its size (a file),
/// else block by block.
std::string ReadRest(std::istream& in);

/// Why the file at `path` cannot be read as a regular file, or "" if it can: "not a regular
/// file" (a folder, a device), else the system's reason ("No such file or directory", "File
/// name too long"). Never throws, whatever `path` holds.
std::string UnreadableFileReason(const std::string& path);

/// Writes `text` to `path` atomically: a temporary file in the same folder, renamed into place
/// once complete, so a failed run never leaves a partial file that looks complete. Missing
/// parent folders are created. The file gets the usual 0666 & ~umask permissions.
/// @throws std::runtime_error "<path>: cannot write the file: <reason>"; no temporary file is
///         left behind.
void WriteFileAtomically(const std::string& path, const std::string& text);

/// Checks, before any work, the output `path` given with command-line `option`: empty (not
/// asked for) passes; a folder, which could never be written as a file, does not.
/// @throws InputError "<option> <path>: is a directory"
void CheckOutputPath(const std::string& option, const std::string& path);

}  // namespace acdplan
