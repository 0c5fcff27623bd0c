// The shipped NAO V5 model (models/nao_v5.urdf) as the model and world tests
// use it, once: its path, its text, and the model loaded once per test program.
#pragma once

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "sim/nao_model/RobotModel.hpp"

namespace simswift::testing {

inline const std::string kNaoV5UrdfPath = std::string(SIMSWIFT_SOURCE_DIR) + "/models/nao_v5.urdf";

inline std::string readNaoV5Urdf() {
  std::ifstream in(kNaoV5UrdfPath);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::shared_ptr<const RobotModel> naoV5Model() {
  static const auto model = std::make_shared<const RobotModel>(RobotModel::loadUrdf(kNaoV5UrdfPath));
  return model;
}

}  // namespace simswift::testing
