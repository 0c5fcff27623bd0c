// Python bindings of the public API (include/simswift/): `import simswift`.
//
//   sim = simswift.Simulation("scenarios/walk_one.yaml")
//   sim.step(); sim.run(2.0); sim.run(5.0, until=lambda sim: sim.robot(0).fallen)
//   b = sim.ball                      # .present, .x .y .z (m), .vx .vy .vz (m/s)
//   s = sim.robot(0).sensors          # named numpy arrays: fsr (8, kg),
//   s.fsr.sum(), s.gyroscope, ...     # gyroscope, accelerometer, joint_angles, ...
//   sim.robot(0).set_controller(lambda s, j: ...)   # j.angles / j.stiffnesses (numpy, in place)
//   table = simswift.run_experiment("scenarios/findball_quick.yaml", jobs=2)
//   t = simswift.WalkTest(7, gait)     # gait(command, sensors, joints): the walk test kit
//   f = t.walk(forward=200); f.forward_ratio, f.falls, f.summary()
//
// Errors become Python exceptions: simswift.ConfigError (with .file, .line,
// .key) for bad files, ValueError / IndexError / RuntimeError otherwise.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>

#include "simswift/Experiment.hpp"
#include "simswift/Simulation.hpp"
#include "simswift/WalkTest.hpp"

namespace py = pybind11;
namespace sa = simswift::api;

namespace {

py::array_t<float> copy(const float* v, int n) {
  py::array_t<float> a(n);
  std::memcpy(a.mutable_data(), v, sizeof(float) * static_cast<size_t>(n));
  return a;
}

// The sensors of one tick as named arrays (copies; units as on the NAO).
struct PySensors {
  explicit PySensors(const sa::SensorValues& s) : raw(s) {}
  sa::SensorValues raw;
  py::array_t<float> jointAngles() const { return copy(raw.joints.angles, sa::kNumJoints); }
  py::array_t<float> jointStiffnesses() const { return copy(raw.joints.stiffnesses, sa::kNumJoints); }
  py::array_t<float> fsr() const {  // kg: left FL FR RL RR, right FL FR RL RR
    const float v[8] = {raw.sensors[sa::LFsrFrontLeft], raw.sensors[sa::LFsrFrontRight],
                        raw.sensors[sa::LFsrRearLeft],  raw.sensors[sa::LFsrRearRight],
                        raw.sensors[sa::RFsrFrontLeft], raw.sensors[sa::RFsrFrontRight],
                        raw.sensors[sa::RFsrRearLeft],  raw.sensors[sa::RFsrRearRight]};
    return copy(v, 8);
  }
  py::array_t<float> gyroscope() const { return copy(&raw.sensors[sa::GyroscopeX], 3); }          // rad/s
  py::array_t<float> accelerometer() const { return copy(&raw.sensors[sa::AccelerometerX], 3); }  // m/s^2
  py::array_t<float> angle() const { return copy(&raw.sensors[sa::AngleX], 2); }                  // rad
  py::array_t<float> sensors() const { return copy(raw.sensors, sa::kNumSensors); }
  py::array_t<float> sonar() const { return copy(raw.sonar, sa::kNumSonars); }  // m
};

// A command a Python controller fills in place.
struct PyJoints {
  py::array_t<float> angles{sa::kNumJoints}, stiffnesses{sa::kNumJoints};
};

// The walk test kit's reference walk, callable from Python as a gait.
struct PyGait {
  sa::Gait gait;
};

void translateConfigError(const sa::ConfigError& e, const py::object& type) {
  py::object err = type(e.what());
  err.attr("file") = e.file;
  err.attr("line") = e.line;
  err.attr("key") = e.key;
  PyErr_SetObject(type.ptr(), err.ptr());
}

}  // namespace

PYBIND11_MODULE(simswift, m) {
  m.doc() = "simswift: NAO V5 robot-soccer simulation (ODE physics, libagent's interface at 10 ms)";
  static py::exception<sa::ConfigError> config_error(m, "ConfigError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const sa::ConfigError& e) {
      translateConfigError(e, config_error);
    }
  });

  py::class_<PySensors>(m, "Sensors")
      .def_property_readonly("joint_angles", &PySensors::jointAngles)
      .def_property_readonly("joint_stiffnesses", &PySensors::jointStiffnesses)
      .def_property_readonly("fsr", &PySensors::fsr)
      .def_property_readonly("gyroscope", &PySensors::gyroscope)
      .def_property_readonly("accelerometer", &PySensors::accelerometer)
      .def_property_readonly("angle", &PySensors::angle)
      .def_property_readonly("sensors", &PySensors::sensors)
      .def_property_readonly("sonar", &PySensors::sonar);

  py::class_<PyJoints>(m, "Joints")
      .def_readonly("angles", &PyJoints::angles)
      .def_readonly("stiffnesses", &PyJoints::stiffnesses);

  py::class_<sa::Pose>(m, "Pose")
      .def_readonly("x", &sa::Pose::x)
      .def_readonly("y", &sa::Pose::y)
      .def_readonly("z", &sa::Pose::z)
      .def_readonly("theta", &sa::Pose::theta);

  py::class_<sa::BallState>(m, "Ball")  // m and m/s, field frame
      .def_readonly("present", &sa::BallState::present)
      .def_readonly("x", &sa::BallState::x)
      .def_readonly("y", &sa::BallState::y)
      .def_readonly("z", &sa::BallState::z)
      .def_readonly("vx", &sa::BallState::vx)
      .def_readonly("vy", &sa::BallState::vy)
      .def_readonly("vz", &sa::BallState::vz);

  py::class_<sa::Robot>(m, "Robot")
      .def_property_readonly("index", &sa::Robot::index)
      .def_property_readonly("sensors", [](const sa::Robot& r) { return PySensors(r.sensors()); })
      .def_property_readonly("pose", &sa::Robot::pose)
      .def_property_readonly("fallen", &sa::Robot::fallen)
      .def_property_readonly("falls", &sa::Robot::falls)
      .def("set_joints",
           [](sa::Robot& r, py::array_t<float, py::array::c_style | py::array::forcecast> angles,
              py::array_t<float, py::array::c_style | py::array::forcecast> stiffnesses) {
             if (angles.size() != sa::kNumJoints || stiffnesses.size() != sa::kNumJoints)
               throw py::value_error("set_joints: angles and stiffnesses need 25 values each (libagent's joints)");
             sa::JointValues j{};
             std::memcpy(j.angles, angles.data(), sizeof j.angles);
             std::memcpy(j.stiffnesses, stiffnesses.data(), sizeof j.stiffnesses);
             r.setJoints(j);
           },
           py::arg("angles"), py::arg("stiffnesses"))
      .def("set_controller",
           [](sa::Robot& r, py::function f) {
             auto joints = std::make_shared<PyJoints>();
             r.setController([f, joints](const sa::SensorValues& s, sa::JointValues& j) {
               py::gil_scoped_acquire gil;
               std::memcpy(joints->angles.mutable_data(), j.angles, sizeof j.angles);
               std::memcpy(joints->stiffnesses.mutable_data(), j.stiffnesses, sizeof j.stiffnesses);
               f(PySensors(s), py::cast(joints.get(), py::return_value_policy::reference));
               std::memcpy(j.angles, joints->angles.data(), sizeof j.angles);
               std::memcpy(j.stiffnesses, joints->stiffnesses.data(), sizeof j.stiffnesses);
             });
           },
           py::arg("controller"))
      .def("push", &sa::Robot::push, py::arg("jx"), py::arg("jy"))
      .def("teleport", &sa::Robot::teleport, py::arg("x"), py::arg("y"), py::arg("theta"));

  py::class_<sa::Simulation>(m, "Simulation")
      .def(py::init([](const std::string& path) { return sa::Simulation::fromScenario(path); }), py::arg("scenario"))
      .def_static("from_yaml", &sa::Simulation::fromYaml, py::arg("text"), py::arg("name") = "<yaml>",
                  py::arg("base_dir") = ".")
      .def("step", &sa::Simulation::step)
      // until(sim) is called after each tick; a true value stops the run.
      .def(
          "run",
          [](py::object self, double seconds, py::object until) {
            sa::Simulation& s = self.cast<sa::Simulation&>();
            if (until.is_none()) return s.run(seconds);
            return s.run(seconds, [&](const sa::Simulation&) { return py::bool_(until(self)).cast<bool>(); });
          },
          py::arg("seconds"), py::arg("until") = py::none(),
          "Steps for `seconds` of simulated time, or until until(sim) is true; returns the seconds stepped.")
      .def("robot", &sa::Simulation::robot, py::arg("index"), py::keep_alive<0, 1>())
      .def_property_readonly("num_robots", &sa::Simulation::numRobots)
      .def_property_readonly("time", &sa::Simulation::time)
      .def_property_readonly("ticks", &sa::Simulation::ticks)
      .def_property_readonly("state_hash", &sa::Simulation::stateHash)
      .def_property_readonly("ball", &sa::Simulation::ball)
      .def("place_ball", &sa::Simulation::placeBall, py::arg("x"), py::arg("y"))
      .def("record", &sa::Simulation::record, py::arg("path"), py::arg("rate_hz") = 20.0,
           "record the run from the next step on as MCAP (docs/recording.md)")
      .def("finish_recording", &sa::Simulation::finishRecording, "complete and close the recording");

  m.def(
      "run_experiment",
      [](const std::string& file, int jobs, const std::string& out) {
        sa::ExperimentOptions o;
        o.jobs = jobs;
        o.out_dir = out;
        const sa::ResultsTable t = sa::runExperiment(file, o);
        py::list rows;
        for (const auto& r : t.rows) {
          py::dict d;
          for (size_t i = 0; i < t.columns.size() && i < r.size(); ++i) d[py::str(t.columns[i])] = r[i];
          rows.append(d);
        }
        return rows;
      },
      py::arg("file"), py::arg("jobs") = 0, py::arg("out") = "",
      "Runs an experiment file (every trial in its own process); returns results.csv's rows as dicts.");

  // --- The walk test kit (simswift/WalkTest.hpp) ---
  py::class_<sa::WalkCommand>(m, "WalkCommand", "forward, left (mm/s), turn (rad/s), walk (False: stand)")
      .def(py::init([](double forward, double left, double turn, bool walk) {
             return sa::WalkCommand{forward, left, turn, walk};
           }),
           py::arg("forward") = 0.0, py::arg("left") = 0.0, py::arg("turn") = 0.0, py::arg("walk") = true)
      .def_readwrite("forward", &sa::WalkCommand::forward)
      .def_readwrite("left", &sa::WalkCommand::left)
      .def_readwrite("turn", &sa::WalkCommand::turn)
      .def_readwrite("walk", &sa::WalkCommand::walk);

  py::class_<sa::WalkFigures>(m, "WalkFigures", "what a walk achieved over one window (WalkTest.hpp)")
      .def_readonly("commanded", &sa::WalkFigures::commanded)
      .def_readonly("seconds", &sa::WalkFigures::seconds)
      .def_readonly("forward", &sa::WalkFigures::forward)
      .def_readonly("left", &sa::WalkFigures::left)
      .def_readonly("turn", &sa::WalkFigures::turn)
      .def_readonly("forward_ratio", &sa::WalkFigures::forward_ratio)
      .def_readonly("left_ratio", &sa::WalkFigures::left_ratio)
      .def_readonly("turn_ratio", &sa::WalkFigures::turn_ratio)
      .def_readonly("heading_slope", &sa::WalkFigures::heading_slope)
      .def_readonly("falls", &sa::WalkFigures::falls)
      .def_readonly("stances", &sa::WalkFigures::stances)
      .def_readonly("slip_mean", &sa::WalkFigures::slip_mean)
      .def_readonly("slip_max", &sa::WalkFigures::slip_max)
      .def("summary", &sa::WalkFigures::summary)
      .def("__repr__", &sa::WalkFigures::summary);

  // simswift's reference walk as a gait a Python test passes like its own.
  py::class_<PyGait>(m, "ReferenceGait", "simswift's reference walk (Walk2014Generator) as gait(command, sensors, joints)")
      .def(py::init([] { return PyGait{sa::referenceGait()}; }))
      .def("__call__", [](PyGait& g, const sa::WalkCommand& c, const PySensors& s, PyJoints& j) {
        sa::JointValues out{};
        std::memcpy(out.angles, j.angles.data(), sizeof out.angles);
        std::memcpy(out.stiffnesses, j.stiffnesses.data(), sizeof out.stiffnesses);
        g.gait(c, s.raw, out);
        std::memcpy(j.angles.mutable_data(), out.angles, sizeof out.angles);
        std::memcpy(j.stiffnesses.mutable_data(), out.stiffnesses, sizeof out.stiffnesses);
      });

  py::class_<sa::WalkTest>(m, "WalkTest", "one robot driven by gait(command, sensors, joints); see simswift/WalkTest.hpp")
      .def(py::init([](uint64_t seed, py::function gait, bool noise, double x, double y, double theta) {
             auto joints = std::make_shared<PyJoints>();
             sa::Gait g = [gait, joints](const sa::WalkCommand& c, const sa::SensorValues& s, sa::JointValues& j) {
               py::gil_scoped_acquire gil;
               std::memcpy(joints->angles.mutable_data(), j.angles, sizeof j.angles);
               std::memcpy(joints->stiffnesses.mutable_data(), j.stiffnesses, sizeof j.stiffnesses);
               gait(c, PySensors(s), py::cast(joints.get(), py::return_value_policy::reference));
               std::memcpy(j.angles, joints->angles.data(), sizeof j.angles);
               std::memcpy(j.stiffnesses, joints->stiffnesses.data(), sizeof j.stiffnesses);
             };
             sa::WalkTestSetup setup;
             setup.seed = seed, setup.noise = noise, setup.x = x, setup.y = y, setup.theta = theta;
             return sa::WalkTest(setup, std::move(g));
           }),
           py::arg("seed"), py::arg("gait"), py::arg("noise") = true, py::arg("x") = -3.0, py::arg("y") = 0.0,
           py::arg("theta") = 0.0)
      .def("command",
           [](sa::WalkTest& t, double forward, double left, double turn, bool walk) {
             t.command({forward, left, turn, walk});
           },
           py::arg("forward") = 0.0, py::arg("left") = 0.0, py::arg("turn") = 0.0, py::arg("walk") = true)
      .def("run", &sa::WalkTest::run, py::arg("seconds"))
      .def("walk",
           [](sa::WalkTest& t, double forward, double left, double turn, double settle, double window) {
             return t.walk({forward, left, turn, true}, settle, window);
           },
           py::arg("forward") = 0.0, py::arg("left") = 0.0, py::arg("turn") = 0.0, py::arg("settle") = 2.0,
           py::arg("window") = 6.0)
      .def("trace", &sa::WalkTest::trace, py::arg("csv_path"))
      .def("stop_trace", &sa::WalkTest::stopTrace)
      .def_property_readonly("falls", [](const sa::WalkTest& t) { return t.sample().falls; })
      .def_property_readonly("pose", [](const sa::WalkTest& t) { return t.sample().torso; })
      .def("robot", &sa::WalkTest::robot, py::keep_alive<0, 1>());

  m.def("reference_gait", [] { return PyGait{sa::referenceGait()}; },
        "simswift's reference walk as a gait(command, sensors, joints)");
  m.def(
      "plot_trace",
      [](const std::string& csv, const std::string& png) {
        std::string message;
        if (!sa::plotTrace(csv, png, &message)) throw std::runtime_error(message);
      },
      py::arg("csv_path"), py::arg("png_path"), "Plots a WalkTest trace to a PNG with gnuplot (RuntimeError if it cannot).");
}
