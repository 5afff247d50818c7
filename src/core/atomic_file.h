// Whole-file writes that never leave a torn file: the contents go to a
// temporary name in the same folder, are flushed to disk, and the temporary
// is renamed over the target (rename is atomic within one file system).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace grainlab {

// Writes `contents` to `path` atomically. On failure removes the temporary
// file, leaves any earlier `path` as it was, and throws naming the path, the
// system's reason and a fix: InputError for an existing target that is no
// regular file (such as /dev/full, which the rename would replace),
// WriteError (core/error.h) for every other failure (a missing folder, a
// name too long, permissions, a read-only or full disk, the file-size limit):
// a command that wants a wrong path called bad input checks it first
// (check_file_target, or the output folder's lock).
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// The checks of write_file_atomically that need no writing, for a command to
// refuse a bad output path before it works for minutes: InputError when
// `path` exists and is no regular file, or its folder does not exist.
void check_file_target(const std::filesystem::path& path);

// What to do about a write that failed with errno `err` (a clause for a message).
std::string fix_for_write_error(int err);
// True for the errors of a wrong path (missing folder, a file in the path, a
// name too long, a folder where a file should be): the user's input, not the system.
bool is_path_error(int err);

// Removes, in `folder` and below, the temporaries write_file_atomically names
// (".NAME.tmp.PID.N") that a killed process left; returns how many. Only for a
// folder no other process writes to (the run's folder, under its lock).
int remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace grainlab
