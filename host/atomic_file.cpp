#include "atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "host_errors.hpp"

namespace peristep::host {

std::string hostName() {
  char host[256] = "";
  ::gethostname(host, sizeof host - 1);
  return host;
}

std::filesystem::path temporaryName(const std::filesystem::path& file) {
  return file.string() + "." + hostName() + "." + std::to_string(::getpid()) + ".tmp";
}

void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes) {
  const std::filesystem::path temporary = temporaryName(file);
  std::error_code ec;
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(temporary, ec);
      throw RunError("cannot write " + file.string() + " (is the disk full or the directory read-only?)");
    }
  }
  std::filesystem::rename(temporary, file, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temporary, ec);
    throw RunError("cannot move " + temporary.string() + " onto " + file.string() + ": " + why);
  }
}

}  // namespace peristep::host
