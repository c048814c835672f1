#pragma once

namespace shelfdock::sim {

/// The lift that raises the shelf once the robot is under it: it takes a fixed time.
class Lift {
 public:
  explicit Lift(double duration_s) : duration_s_(duration_s) {}

  /// Starts lifting at `time_s`; a second call while lifting or lifted is ignored.
  void Start(double time_s);
  bool Started() const { return started_; }
  /// Fraction of the stroke done at `time_s`, in [0, 1].
  double Progress(double time_s) const;
  /// Done once the duration has elapsed (to a nanosecond, so summed control steps count).
  bool Done(double time_s) const;

 private:
  double duration_s_;
  bool started_ = false;
  double start_time_s_ = 0.0;
};

}  // namespace shelfdock::sim
