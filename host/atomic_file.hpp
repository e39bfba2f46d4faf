#pragma once
// Whole files or nothing: a result file is written under a temporary name unique to this host and
// process, "<file>.<host>.<pid>.tmp", in the target directory, and renamed onto its name, so a reader
// (or a second writer) never sees half of it. A failed write (a full disk) removes its temporary.
#include <filesystem>
#include <string>
#include <string_view>

namespace peristep::host {

// Throws RunError, naming the file and the reason.
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// The temporary name writeFileAtomically uses for `file` in this process.
std::filesystem::path temporaryName(const std::filesystem::path& file);

// The ".<host>." part of this host's temporary names.
std::string hostName();

}  // namespace peristep::host
