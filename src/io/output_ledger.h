#pragma once
// What a run writes into its output folder, written down before it is written: the folder's
// ledger, the file .cablefilm.written, lists each file and each folder the run creates there
// (paths relative to the folder, one a line). The next run into the folder removes exactly
// those, with the temporaries of a run that was killed (NAME.tmpPID), and the listed folders
// once they are empty; nothing else in the folder is touched, whatever its name.
#include <string>

namespace cablefilm {

class OutputLedger {
 public:
  OutputLedger() = default;
  ~OutputLedger();  // stops recording; the ledger stays in the folder for the next run
  OutputLedger(const OutputLedger&) = delete;
  OutputLedger& operator=(const OutputLedger&) = delete;

  // Removes what `folder`'s ledger lists (RemoveRecordedOutputs) and starts an empty ledger
  // there, in which RecordOutput writes until this object goes. Throws Error.
  void Open(const std::string& folder);

  static const char kFileName[];  // ".cablefilm.written"

 private:
  void Close();
  std::string folder_;
};

// Writes `path` (a file about to be created or renamed into place) into the open ledger whose
// folder holds it; nothing when no open ledger does. Thread-safe. Throws Error when the ledger
// cannot be written (the file is then not to be written either).
void RecordOutput(const std::string& path);

// A module (modules/) links its own copy of this file: it records through the program's
// ledgers, with the program's RecordOutputOrSay (which returns "" or the error's message, so
// that no exception crosses between the two).
using OutputRecorder = std::string (*)(const std::string& path);
void RecordOutputsThrough(OutputRecorder recorder);
std::string RecordOutputOrSay(const std::string& path);

// Creates `folder` and its missing parents, each written into the ledger first (a folder that
// was already there is not the run's). Throws Error naming the folder.
void CreateOutputFolder(const std::string& folder);

// Removes what `folder`'s ledger lists, the temporaries of its files, the listed folders that
// are left empty (first what a ledger inside such a folder lists, and a lock no run holds
// there), then the ledger itself. A folder without a ledger is left as it is.
void RemoveRecordedOutputs(const std::string& folder);

}  // namespace cablefilm
