// mergeRuns() (Batch.hpp): shard folders of one experiment joined into one.
#include <sstream>
#include <string>
#include <vector>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/ResultsFolder.hpp"

namespace simswift::experiment {

BatchOutcome mergeRuns(const std::vector<std::string>& dirs, const std::string& out_dir) {
  if (dirs.empty()) throw BatchError("merge: no folders given");
  const std::string text = readFile(dirs[0] + "/experiment.yaml");
  for (const std::string& d : dirs)
    if (readFile(d + "/experiment.yaml") != text)
      throw BatchInputError(d + "/experiment.yaml differs from " + dirs[0] +
                            "/experiment.yaml: not shards of one experiment");
  const Experiment e = Experiment::parse(text, dirs[0] + "/experiment.yaml");
  const FolderLock lock = claimFolder(e, out_dir);
  for (const std::string& d : dirs) {
    for (const std::string& f : listTrialFiles(d + "/trials")) {
      const std::string src = d + "/trials/" + f, dst = out_dir + "/trials/" + f;
      const std::string body = readFile(src);
      if (exists(dst)) {
        // Results must agree; timing (wall clock) may differ between hosts.
        if (f.find(".timing.") == std::string::npos && readFile(dst) != body)
          throw BatchError(src + " differs from " + dst + ": the folders disagree about a trial");
        continue;
      }
      writeAtomic(dst, body);
    }
  }
  BatchOutcome o;
  o.trials = e.numTrials();
  std::vector<int> missing;
  for (int t = 0; t < e.numTrials(); ++t)
    if (!trialDone(out_dir, t)) missing.push_back(t);
  o.already = o.trials - static_cast<int>(missing.size());
  if (missing.empty()) {
    std::string notes;
    assemble(e, out_dir, &notes);
    o.assembled = true;
    o.message = notes + "merged " + std::to_string(dirs.size()) + " folder(s) into " + out_dir + ": " +
                std::to_string(o.trials) + " trials";
  } else {
    std::ostringstream m;
    m << "merged into " << out_dir << ", but " << missing.size() << " of " << o.trials
      << " trials are missing (first: " << missing[0] << "); run the missing shards, then merge again";
    o.message = m.str();
    o.failed = static_cast<int>(missing.size());
  }
  return o;
}

}  // namespace simswift::experiment
