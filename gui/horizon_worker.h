// Builds horizon maps (scene/horizon_map.h) on a thread of their own: makeHorizonMap walks
// width * height * directions * kHorizonReachTexels height samples, 0.1 s to 1 s for a 512 x 512
// map, too long for the UI thread. The newest request wins (job_queue.h); the UI installs a
// result only if the material still asks for exactly it (installHorizonMap in material_maps.h).
#pragma once

#include "gui/job_queue.h"
#include "gui/material_maps.h"

#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace twr::gui {

struct HorizonBuilt {
  HorizonRequest request;
  std::shared_ptr<const HorizonMap> map;  // null when the build threw
  std::string error;
  double seconds = 0.0;  // how long the build took
};

class HorizonWorker {
 public:
  HorizonWorker();
  ~HorizonWorker();  // finishes the running build, drops a queued one, joins
  HorizonWorker(const HorizonWorker&) = delete;
  HorizonWorker& operator=(const HorizonWorker&) = delete;

  void submit(HorizonRequest request) { queue_.submit(std::move(request)); }
  bool idle() const { return queue_.idle(); }
  bool hasFinished() const { return queue_.hasFinished(); }
  std::vector<HorizonBuilt> takeFinished() { return queue_.takeFinished(); }

 private:
  void run();

  JobQueue<HorizonRequest, HorizonBuilt> queue_;
  std::thread thread_;  // last member: starts once the others exist
};

}  // namespace twr::gui
