// The camera side of the robot interface: what the Perception thread waits on.
//
// On a NAO, Perception blocks on the camera driver until a frame arrives
// (30 Hz). In simswift the simulator plays the driver: it fills a CameraBlock
// (part of the extension object beside the libagent block, SimExtension.hpp)
// at 30 Hz of simulated time, posts `frame_ready`, and waits on
// `perception_done` (with a watchdog) before stepping on; each hand-over
// also carries a sequence number (frames_posted / frames_done).
//
// A frame carries the vision oracle's observations (what a detector would
// report: robot-relative, mm / rad) and, when rendering is on, the images.
// Image buffers live in a separate block (see CameraImages) so robots that do
// not render pay nothing.
#pragma once

#include <semaphore.h>

#include <atomic>
#include <cstdint>

namespace common::libagent {

// What was seen. Values are fixed (the block is shared between processes):
// append only. LineCorner is a line intersection (kind in Observation::corner).
enum class ObservationType : int32_t { Ball = 0, GoalPost, Robot, LineCorner, FieldLine, CentreCircle, PenaltyCross };

// Kind of a line intersection: L (two lines end at a corner), T (one line
// ends on another), X (two lines cross).
enum class CornerKind : int32_t { None = 0, L = 1, T = 2, X = 3 };

// Observation::flags bits.
constexpr int32_t kObservationRobotFallen = 1;  // Robot: the robot seen is lying on the ground

// One detection, as a detector on the robot would report it (the vision
// oracle's output, already noisy).
//
// Frame: robot-relative, origin on the ground midway between the feet, x
// forward (the torso's heading projected on the ground), y left, z up.
// Units: mm and rad; angles counter-clockwise positive (left).
//
// What each field means per type:
//   x, y          ground point of the object: ball centre's projection,
//                 post base centre, robot (midway between its feet),
//                 intersection point, circle centre, mark centre; for a
//                 FieldLine the first end of the piece seen.
//   distance      mm, sqrt(x^2 + y^2); for a FieldLine the distance to the
//                 nearest point of the piece seen.
//   heading       rad, atan2(y, x) of the same point.
//   x2, y2        FieldLine only: the other end of the piece seen (mm).
//   orientation   rad, robot-relative direction:
//                   Robot: the seen robot's facing;
//                   LineCorner L: bisector of the two arms, pointing into
//                     the corner's inside; T: along the stem, away from the
//                     bar; X: along one of the crossing lines (ambiguous by
//                     a quarter turn for line-line, half a turn for the
//                     halfway line crossing the centre circle);
//                   CentreCircle: along the halfway line (ambiguous by pi);
//                   FieldLine: from (x, y) to (x2, y2);
//                   otherwise 0.
//   corner        LineCorner only: L / T / X; None otherwise.
//   team          Robot only: SPL team number of the robot seen (told by its
//                 jersey colour, whose team the GameController names); -1 otherwise.
//   colour        Robot only: jersey colour seen, 0 blue, 1 red; -1 otherwise.
//   confidence    0..1: the detector model's detection probability at this
//                 distance (1 when noise is off).
//   flags         kObservation* bits.
struct Observation {
  ObservationType type;
  int32_t camera;   // 0 = top, 1 = bottom
  float distance;   // mm
  float heading;    // rad
  float x, y;       // mm, robot-relative
  int32_t team;     // robots: team number seen (or -1)
  CornerKind corner;
  float orientation;  // rad, robot-relative
  float x2, y2;       // mm, robot-relative (FieldLine's second end)
  float confidence;   // 0..1
  int32_t flags;
  int32_t colour;     // robots: 0 blue, 1 red (or -1)
};

// Both cameras together. When more is seen, the oracle keeps the most
// useful (ball, posts, robots, marks, circle, corners, then lines).
constexpr int kMaxObservations = 64;

struct CameraFrame {
  int64_t sim_time_us;  // simulated time the frame was taken
  int64_t frame_index;  // 0, 1, 2, ... at 30 Hz
  int32_t num_observations;
  Observation observations[kMaxObservations];
  int32_t images_valid; // 1 if the CameraImages block holds this frame's images
};

struct CameraBlock {
  uint32_t magic;
  CameraFrame frame;               // written before frame_ready is posted
  sem_t frame_ready;               // posted by the simulator at 30 Hz
  sem_t perception_done;           // posted by Perception when it has finished
  // Hand-over sequence numbers, one per semaphore: the number of frames
  // posted (1, 2, ...), stored (release) by the simulator before it posts
  // frame_ready, and the number Perception has finished, stored (release)
  // before it posts perception_done; each side loads the other's (acquire)
  // after its wait. The semaphore says "wake up", the counter says which
  // frame was handed over: a stray post is not taken for an answer, and the
  // ordering rests on atomics ThreadSanitizer sees (its runtime has no
  // sem_clockwait interceptor, so it sees no edge through that wait).
  std::atomic<int64_t> frames_posted;
  std::atomic<int64_t> frames_done;
  std::atomic<int32_t> shutdown;   // set when the run ends
  // 1 if a Perception thread waits on frame_ready. Set (by announce())
  // before the program answers its first tick; the simulator posts frames
  // (and waits for perception_done) only to robots that have one.
  std::atomic<int32_t> consumer;
};

}  // namespace common::libagent
