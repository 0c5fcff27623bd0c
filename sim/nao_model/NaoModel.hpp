// The NAO as the simulator knows it: a RobotModel loaded from its URDF
// (RobotModel.hpp, any URDF) and, checked apart, its binding to libagent's
// 25 joints (NaoBinding.hpp).
#pragma once

#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"
