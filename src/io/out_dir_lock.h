#pragma once
// One run at a time in an output folder (issue 22 item 4): two runs into the same folder left
// it mixed (one's equilibrium beside the other's time series), both exiting 0. A run holds an
// exclusive lock (flock) on the file .cablefilm.lock in the folder from before it clears the
// folder until it ends; a second run is refused with the first one's process id. The lock goes
// with the process (whatever ends it); the file is removed when the holder lets it go, and a
// file left by a killed run is taken over by the next. Holding the lock, the run keeps the
// folder's ledger (io/output_ledger.h): it removes what the earlier run wrote and lists what
// this one writes.
#include <string>

#include "io/output_ledger.h"

namespace cablefilm {

class OutDirLock {
 public:
  OutDirLock() = default;
  ~OutDirLock();
  OutDirLock(const OutDirLock&) = delete;
  OutDirLock& operator=(const OutDirLock&) = delete;

  // Locks `folder` (which exists) for this process, or throws Error naming the folder and the
  // process that holds it. `what` names the folder in the message ("output folder"). Then
  // removes what the earlier run there wrote and opens the folder's ledger.
  void Lock(const std::string& folder, const std::string& what);

  static const char kFileName[];  // ".cablefilm.lock"

 private:
  void Release();
  std::string path_;
  int fd_ = -1;
  OutputLedger ledger_;
};

}  // namespace cablefilm
