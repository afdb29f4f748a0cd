// One writer per output directory: a run that writes a campaign to `--out DIR`
// claims DIR first — creates it empty if absent and holds an exclusive flock(2) on it — so that
// a second run on the same DIR fails at once with "another run is writing DIR" instead of
// racing it; the lock ends with the process, so a killed run leaves no stale lock. The campaign
// is then written to a temporary sibling and renamed over the empty DIR (campaign_yaml.cc).
#pragma once

#include <string>

namespace uuvplan::io {

class OutputClaim {
 public:
  /// Claims `dir`; model::InputError when it exists and is not empty (nothing is overwritten)
  /// or another run holds it. A claim this process already holds is shared (nested).
  explicit OutputClaim(const std::string& dir);
  /// Releases the claim; removes `dir` if this claim created it and it is still empty (the run
  /// failed before writing anything).
  ~OutputClaim();
  OutputClaim(const OutputClaim&) = delete;
  OutputClaim& operator=(const OutputClaim&) = delete;

 private:
  std::string path_;
  int fd_ = -1;  ///< -1: a nested claim
  bool created_ = false;
};

/// fsync(2) of the directory `dir` (its entries: a rename into it is durable); errors ignored
/// where the file system cannot sync a directory.
void SyncDirectory(const std::string& dir);

}  // namespace uuvplan::io
