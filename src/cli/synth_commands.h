// The two scene kinds of `armmimic-cli synth`, each in its own file.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "command.h"

namespace armmimic::synth {
struct CapsuleArmSceneOptions;
}  // namespace armmimic::synth

namespace armmimic::cli {

int RunSynthArm(const std::vector<std::string>& args,
                const GlobalOptions& global);  // cmd_synth_arm.cpp
int RunSynthMarker(const std::vector<std::string>& args,
                   const GlobalOptions& global);  // cmd_synth_marker.cpp

// Writes a capsule scene (synth arm --generator capsule) and reports it; cmd_synth_capsule.cpp.
int WriteCapsuleScene(const synth::CapsuleArmSceneOptions& options, const std::string& outdir,
                      const GlobalOptions& global);

// Runs one scene writer (synth::WriteArmScene or WriteMarkerScene, given `progress` and `cancel`)
// under an InterruptGuard with a progress bar of `total` steps, and reports its failure: an
// interruption with `interrupted_note` (what the interruption left of the output folder),
// anything else in the library's words. kExitOk, or kExitFailure after the message.
using SceneWriter = std::function<Status(const std::function<void(int, int)>& progress,
                                         const std::atomic<bool>* cancel)>;
int WriteSceneWithProgress(const std::string& kind, int total, const GlobalOptions& global,
                           const SceneWriter& write, const std::string& interrupted_note);

}  // namespace armmimic::cli
