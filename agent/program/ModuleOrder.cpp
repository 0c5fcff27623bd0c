#include "agent/program/ModuleOrder.hpp"

#include "agent/behaviour/ActionsBehaviour.hpp"

#include "common/random/DeriveSeed.hpp"

namespace agent::program {

void buildSchedule(ProgramConfig& cfg, EffectorModule::Sink effector, const common::libagent::CameraImages* images,
                   const common::nao::CameraLens& lens, framework::ModuleSchedule& s) {
  using T = framework::ThreadId;
  using framework::SectionId;
  s.providedByProgram(T::Motion, SectionId::Sensors);
  s.providedByProgram(T::Perception, SectionId::Frame);
  s.providedByProgram(T::Perception, SectionId::GameController);
  s.providedByProgram(T::Perception, SectionId::TeamInbox);
  s.readByProgram(SectionId::FindBall);    // the simulator's FindBall view
  s.readByProgram(SectionId::TeamOutbox);  // the program puts it on the team transport

  // Perception.
  if (cfg.perception_step)
    s.add(T::Perception, std::make_unique<PerceptionStepModule>(std::move(cfg.perception_step), images));
  s.add(T::Perception, std::make_unique<GameStateModule>(cfg.team, cfg.player));
  s.add(T::Perception, std::make_unique<perception::VisionAdapterModule>(cfg.vision));
  localisation::LocalisationModuleConfig lc = cfg.localisation;
  // Per robot (cfg.seed: the scenario's program seed), and still moved by the
  // filter config's own seed.
  using common::random::deriveSeed;
  lc.filter.seed = deriveSeed(deriveSeed(cfg.seed, common::random::seed_tag::kLocalisation), lc.filter.seed);
  s.add(T::Perception, std::make_unique<localisation::LocalisationModule>(lc));
  s.add(T::Perception, std::make_unique<perception::BallTrackerModule>(cfg.ball));
  s.add(T::Perception, std::make_unique<TeamReceiveModule>(cfg.team, cfg.player));
  if (cfg.behaviour_config && !cfg.behaviour_config->behaviour.skills.camera_hfov)
    cfg.behaviour_config->behaviour.skills.camera_hfov = lens.horizontal_fov;  // the body's own lens
  if (cfg.behaviour)
    s.add(T::Perception, std::move(cfg.behaviour));
  else if (cfg.behaviour_config)
    s.add(T::Perception, std::make_unique<behaviour::BehaviourModule>(*cfg.behaviour_config));
  else if (!cfg.actions.empty())
    s.add(T::Perception, std::make_unique<behaviour::ActionsBehaviour>(std::move(cfg.actions)));
  s.add(T::Perception, std::make_unique<TeamSendModule>(cfg.team, cfg.player));

  // Motion.
  if (cfg.motion_generator)
    s.add(T::Motion, std::make_unique<GeneratorModule>(std::move(cfg.motion_generator)));
  else
    s.add(T::Motion, std::make_unique<MotionThreadModule>(cfg.motion));
  s.add(T::Motion, std::make_unique<EffectorModule>(std::move(effector)));
}

}  // namespace agent::program
