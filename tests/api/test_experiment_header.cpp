// include/simswift/Experiment.hpp on its own: runExperiment says it throws
// ConfigError, so a file including only this header can catch it (issue 34:
// the type was declared only in Simulation.hpp).
#include "simswift/Experiment.hpp"

#include <gtest/gtest.h>

#include <string>

TEST(ExperimentHeader, AFileIncludingOnlyItCatchesTheConfigError) {
  try {
    simswift::runExperiment("/no/such/experiment.yaml");
    FAIL() << "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, "/no/such/experiment.yaml");
    EXPECT_EQ(e.line, 1);
  }
}
