#include "io/file_util.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace rt {
namespace {

// Slots for the temporary files being written, readable from a signal handler: a slot's
// path is complete before its flag is set, and the flag is cleared before the slot is reused.
// A handful suffices: the program writes its outputs from one thread, the kernel cache aside.
constexpr int kSlots = 8;
struct PendingSlot {
  std::atomic<bool> used{false};
  std::atomic<bool> live{false};
  char path[PATH_MAX];
};
PendingSlot g_pending[kSlots];

int claim_slot() {
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (g_pending[i].used.compare_exchange_strong(expected, true)) return i;
  }
  return -1;  // All busy: the file is still written, just not cleaned up on a signal.
}

void release_slot(int slot) {
  if (slot < 0) return;
  g_pending[slot].live.store(false);
  g_pending[slot].used.store(false);
}

// Returns 0 or the errno of the failed write.
int write_all(int fd, const uint8_t* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return ENOSPC;  // No progress and no error: treat as a full device.
    data += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

std::string parent_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// mkstemp creates files readable by the owner only; outputs get the usual 0666 & ~umask.
mode_t output_mode() {
  static const mode_t mode = [] {
    mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

// Best effort: makes the rename itself durable. Failure here does not undo a complete write.
void sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::string errno_text(int err) { return std::generic_category().message(err); }

int read_file(const std::string& path, std::vector<uint8_t>* data) {
  data->clear();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  struct stat st;
  int err = ::fstat(fd, &st) != 0 ? errno : (S_ISDIR(st.st_mode) ? EISDIR : 0);
  uint8_t buf[1 << 16];
  while (err == 0) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno;
    if (n <= 0) break;
    data->insert(data->end(), buf, buf + n);
  }
  ::close(fd);
  if (err != 0) data->clear();
  return err;
}

int write_file_atomic(const std::string& path, const void* data, size_t size) {
  const std::string dir = parent_of(path);
  // The temporary's name is short whatever the final name's length, so it always fits the
  // file system's name limit where the final name does.
  std::string templ = dir + "/.rt-XXXXXX";
  const int slot = claim_slot();
  const int fd = ::mkostemp(templ.data(), O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    release_slot(slot);
    return err;
  }
  if (slot >= 0 && templ.size() < sizeof g_pending[slot].path) {
    std::memcpy(g_pending[slot].path, templ.c_str(), templ.size() + 1);
    g_pending[slot].live.store(true);
  }
  int err = ::fchmod(fd, output_mode()) != 0 ? errno : 0;
  if (err == 0) err = write_all(fd, static_cast<const uint8_t*>(data), size);
  // fsync before rename: otherwise a crash can leave an empty file under the final name.
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && std::rename(templ.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) ::unlink(templ.c_str());
  release_slot(slot);
  if (err == 0) sync_directory(dir);
  return err;
}

void remove_pending_temporaries() {
  for (PendingSlot& s : g_pending)
    if (s.live.load()) ::unlink(s.path);
}

// Letter case is folded on every platform, not only where the file system folds it: scenes
// and their outputs move between Linux and file systems that fold case (the defaults of
// macOS and Windows, FAT and exFAT, SMB shares), where two names that differ only in case
// are one file; and whether a folder folds case could only be learnt by writing in it.
// Only ASCII letters are folded; other characters are compared as they are.
std::string same_file_key(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p =
      std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  if (ec) p = std::filesystem::absolute(path, ec).lexically_normal();
  std::string key = p.string();
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

}  // namespace rt
