// Battery: charge fraction drained by a constant current. The NAO V5's
// 2.25 Ah pack at the default -1.5 A lasts 1.5 h; a match half is 10 min.
#pragma once

namespace simswift::sensors {

class Battery {
 public:
  Battery(double start_charge, double current, double capacity_ah)
      : charge_(start_charge), current_(current), capacity_ah_(capacity_ah) {}
  // Advances dt (s); negative current discharges. Charge stays in 0..1.
  void step(double dt);
  double charge() const { return charge_; }    // 0..1
  double current() const { return current_; }  // A

 private:
  double charge_;
  double current_;
  double capacity_ah_;
};

}  // namespace simswift::sensors
