// Output folders at the edge of the system: made with a message for people, not
// std::filesystem's ("filesystem error: cannot create directories: Not a directory [out/x]").
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace l2 {

// Makes `folder` and its missing parents; nothing when it is a folder already. Throws
// std::runtime_error, one line naming the path (after `what` and ": " when given, e.g. "--out"):
//   "out: a file, not a folder"                                    (the folder is a file)
//   "out/x: cannot make the folder: out is a file, not a folder"   (a parent is a file)
//   "out/x: cannot make the folder: Permission denied"             (any other reason)
void make_folders(const std::filesystem::path& folder, const std::string& what = "");

// Opens `file` for writing, creating it (its content is left for the writer to replace), and
// closes it again: a library that writes files (OpenImageIO) does not say why it cannot open one
// ("Could not open file"). Throws std::runtime_error "<file>: cannot write: a folder, not a
// file" or "<file>: cannot write: <the system's reason>" (e.g. Permission denied).
void check_writable(const std::filesystem::path& file);

// Throws std::runtime_error "<what> <folder>: cannot write into the folder: <the system's
// reason>" (Read-only file system, Permission denied) when no file can be made in `folder`, a
// folder that exists: found before a program starts work whose output would be lost there.
void check_folder_writable(const std::filesystem::path& folder, const std::string& what = "");

// Writes `bytes` as `file`, whole or not at all: into a file of its own beside it first, renamed
// to `file` once every byte is written and closed. A file system that is full or read-only
// leaves no file cut short under the name, and an earlier file of that name as it was. Throws
// std::runtime_error "<file>: cannot write: a folder, not a file" or "<file>: cannot write:
// <the system's reason>" (No space left on device).
void write_whole_file(const std::filesystem::path& file, std::string_view bytes);

// `error` (a file that could not be written, named) with what the output folder `out` holds of
// this run: "<error>; <out> holds only part of this run: <written>, <missing>" ("display-0.png",
// "no report.json"), or, with `written` empty (nothing of this run written yet), the error alone.
std::runtime_error partly_written(const std::runtime_error& error, const std::filesystem::path& out,
                                  const std::string& written, const std::string& missing);

// Whether `name` is `prefix`, at least `min_digits` decimal digits and `suffix`, nothing else:
// the names a program gives its numbered outputs ("frame-12", "frame-0003.png").
bool numbered_name(std::string_view name, std::string_view prefix, std::string_view suffix = {},
                   std::size_t min_digits = 1);

// Removes what an earlier run left in `folder`, where it would stand beside this run's output as
// if this run had made it: every entry `earlier` picks, a folder with its contents. Nothing else
// is touched; a missing folder is nothing to do. Throws std::runtime_error
// "<entry>: cannot remove <what>: <the system's reason>".
void remove_earlier(const std::filesystem::path& folder,
                    const std::function<bool(const std::filesystem::directory_entry&)>& earlier,
                    const std::string& what);

}  // namespace l2
