#include "image/folders.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace l2 {

namespace {

// The first part of `folder` that exists and is not a folder (empty if none), and whether it is
// the whole of `folder`.
std::pair<std::filesystem::path, bool> first_non_folder(const std::filesystem::path& folder) {
  std::filesystem::path part;
  for (auto name = folder.begin(); name != folder.end(); ++name) {
    if (name->empty()) continue;  // after a trailing slash
    part /= *name;
    std::error_code error;
    const auto status = std::filesystem::status(part, error);
    if (error) break;  // missing, or not to be looked into: the reason says why
    if (!std::filesystem::is_directory(status)) {
      auto rest = std::next(name);
      while (rest != folder.end() && rest->empty()) ++rest;
      return {part, rest == folder.end()};
    }
  }
  return {{}, false};
}

std::string kind(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) ? "a file" : "something else";
}

}  // namespace

void make_folders(const std::filesystem::path& folder, const std::string& what) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (!error) return;
  const std::string name = (what.empty() ? "" : what + " ") + folder.string();
  const auto [in_the_way, whole] = first_non_folder(folder);
  if (whole) throw std::runtime_error(name + ": " + kind(in_the_way) + ", not a folder");
  if (!in_the_way.empty()) {
    throw std::runtime_error(name + ": cannot make the folder: " + in_the_way.string() + " is " +
                             kind(in_the_way) + ", not a folder");
  }
  throw std::runtime_error(name + ": cannot make the folder: " + error.message());
}

void check_writable(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
  if (fd >= 0) {
    ::close(fd);
    return;
  }
  const int error = errno;
  throw std::runtime_error(file.string() + ": cannot write: " +
                           (error == EISDIR ? "a folder, not a file" : std::strerror(error)));
}

void check_folder_writable(const std::filesystem::path& folder, const std::string& what) {
  const std::string probe = (folder / (".write-test-" + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
    return;
  }
  const int error = errno;
  throw std::runtime_error((what.empty() ? "" : what + " ") + folder.string() +
                           ": cannot write into the folder: " + std::strerror(error));
}

namespace {

// Every byte, or errno.
int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

// A name beside `file` that no other writer, in this process or another, uses.
std::string temporary_name(const std::filesystem::path& file) {
  static std::atomic<unsigned> count{0};
  return file.string() + ".part-" + std::to_string(::getpid()) + "-" + std::to_string(count++);
}

}  // namespace

void write_whole_file(const std::filesystem::path& file, std::string_view bytes) {
  const auto refuse = [&](int error) {
    throw std::runtime_error(file.string() + ": cannot write: " +
                             (error == EISDIR ? "a folder, not a file" : std::strerror(error)));
  };
  std::error_code ignored;
  if (std::filesystem::is_directory(file, ignored)) refuse(EISDIR);
  const std::string temp = temporary_name(file);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) refuse(errno);
  int error = write_all(fd, bytes);
  // close() reports what a file system only finds out then (a network one, a quota).
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temp.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temp.c_str());
    refuse(error);
  }
}

std::runtime_error partly_written(const std::runtime_error& error, const std::filesystem::path& out,
                                  const std::string& written, const std::string& missing) {
  if (written.empty()) return error;
  return std::runtime_error(std::string(error.what()) + "; " + out.string() +
                            " holds only part of this run: " + written + ", " + missing);
}

bool numbered_name(std::string_view name, std::string_view prefix, std::string_view suffix,
                   std::size_t min_digits) {
  if (name.size() < prefix.size() + suffix.size() + std::max<std::size_t>(min_digits, 1) ||
      !name.starts_with(prefix) || !name.ends_with(suffix)) {
    return false;
  }
  const std::string_view digits =
      name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

void remove_earlier(const std::filesystem::path& folder,
                    const std::function<bool(const std::filesystem::directory_entry&)>& earlier,
                    const std::string& what) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (!earlier(entry)) continue;
    if (std::filesystem::remove_all(entry.path(), error); error) {
      throw std::runtime_error(entry.path().string() + ": cannot remove " + what + ": " +
                               error.message());
    }
  }
}

}  // namespace l2
