#pragma once
/// Checks made before any file a user names is read (case, mesh, VTU and PVTU, PVD, history,
/// summary, checkpoint): it must be a regular file (a FIFO would block the reader forever, a
/// device such as /dev/zero never ends) and not larger than what its reader accepts (a sparse
/// file can claim terabytes it does not hold).
#include <cstdint>
#include <filesystem>
#include <string>

namespace plisse {

/// Throws InputError {file = path, key = ""} when `path` does not exist, cannot be opened, is not
/// a regular file (saying what it is: a directory, a FIFO, a device, a socket) or is larger than
/// `max_bytes` ("is N bytes; a <what> is at most M bytes"). Opening does not block on a FIFO.
void check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                      const std::string& what);

/// The memory this process may use [bytes]: the machine's physical memory (sysconf), or 2^40 when
/// it cannot be told, and at most the address-space limit (RLIMIT_AS, ulimit -v).
std::uint64_t physical_memory_bytes();

}  // namespace plisse
