// A robot's heading drift over a walk (a measurement for the motion
// benchmark and tests, not part of the simulation): the least-squares slope
// of the accumulated heading change against time. Steadier than
// (end - start) / duration, which depends on where in the walk cycle the
// window ends (the torso yaws back and forth every two steps).
#pragma once

namespace simswift::runner {

class HeadingDrift {
 public:
  // One sample: `t` s since the start, `turned` rad of heading change since then.
  void add(double t, double turned) {
    ++n_;
    st_ += t;
    sy_ += turned;
    stt_ += t * t;
    sty_ += t * turned;
  }
  // rad/s; 0 with fewer than two samples.
  double slope() const {
    const double den = n_ * stt_ - st_ * st_;
    return n_ < 2 || den == 0 ? 0.0 : (n_ * sty_ - st_ * sy_) / den;
  }

 private:
  double n_ = 0, st_ = 0, sy_ = 0, stt_ = 0, sty_ = 0;
};

}  // namespace simswift::runner
