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
