// A new output directory written whole or not at all: everything goes to a temporary sibling
// directory (mkdtemp: unique to the run), renamed into place at the end. Used by the campaign
// writer (campaign_yaml.h) and the report (`uuvplan report`).
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace uuvplan::io {

/// `dir` without a trailing separator ("dir/" and "dir" are the same directory).
std::filesystem::path DirectoryPath(const std::string& dir);

/// Throws model::InputError naming `dir` when it exists and is not empty (nothing is
/// overwritten); `flag` is the option that chose it (e.g. "--out").
void CheckNewDirectory(const std::string& dir, const std::string& flag);

/// A new, empty directory beside `out`, unique to this call.
std::filesystem::path NewSiblingDirectory(const std::filesystem::path& out, const std::string& dir);

/// Renames the finished `tmp` to `out` (an empty `out` made by the user is replaced). When
/// another run put `what` ("a campaign") there first, the rename fails and says so; `tmp` is
/// then removed.
void MoveIntoPlace(const std::filesystem::path& tmp, const std::filesystem::path& out,
                   const std::string& dir, const std::string& what);

/// Writes `files` (path relative to `dir` → content) into the new directory `dir`, whole or
/// not at all; `dir` must not exist or be empty (`flag` names the option that chose it).
void WriteNewDirectory(const std::string& dir, const std::map<std::string, std::string>& files,
                       const std::string& flag, const std::string& what);

}  // namespace uuvplan::io
