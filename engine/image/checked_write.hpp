// Writing a whole file so that a failure is never silent and never leaves a partial file under
// the final name. Every output of vkwater (EXR, PNG, POV-Ray, reports) goes through here:
// - a regular file (or a name not yet taken) is written to a temporary file in the same folder,
//   flushed to the disk (fsync) and renamed over the final name: readers see the old file or the
//   whole new one, never a partial one;
// - anything else that exists (a device such as /dev/null or /dev/full, a FIFO, /dev/stdout) is
//   written in place, never renamed over, with every write and the close checked.
#pragma once

#include <filesystem>
#include <string_view>

namespace vkw {

// Throws UserError "cannot write '<path>': <why>" (one line) when any step fails; on failure a
// temporary file is removed and the final name keeps what it held before.
void write_file_checked(const std::filesystem::path& path, std::string_view bytes);

}  // namespace vkw
