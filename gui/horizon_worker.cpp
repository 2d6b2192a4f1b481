#include "gui/horizon_worker.h"
#include "gui/worker_priority.h"

#include <chrono>
#include <exception>
#include <stdexcept>

namespace twr::gui {

HorizonWorker::HorizonWorker() : thread_([this] { run(); }) {}

HorizonWorker::~HorizonWorker() {
  queue_.stop();
  thread_.join();
}

void HorizonWorker::run() {
  lowerThisThreadPriority();  // like the renderers: the UI's frames come first
  while (std::optional<HorizonRequest> request = queue_.next()) {
    HorizonBuilt built;
    built.request = *request;
    const auto start = std::chrono::steady_clock::now();
    try {
      if (!request->heightMap) throw std::runtime_error("no height map");
      built.map = std::make_shared<const HorizonMap>(
          makeHorizonMap(*request->heightMap, request->heightScale, request->directions));
    } catch (const std::exception& e) {
      built.error = e.what();
    }
    built.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    queue_.finish(std::move(built));
  }
}

}  // namespace twr::gui
