// How often each move of a birth-death chain was proposed and accepted.
#pragma once

namespace shapeproc::sample {

struct MoveCounts {
  long long births_accepted = 0, births_proposed = 0;
  long long deaths_accepted = 0, deaths_proposed = 0;
  long long shifts_accepted = 0, shifts_proposed = 0;

  MoveCounts& operator+=(const MoveCounts& other) {
    births_accepted += other.births_accepted;
    births_proposed += other.births_proposed;
    deaths_accepted += other.deaths_accepted;
    deaths_proposed += other.deaths_proposed;
    shifts_accepted += other.shifts_accepted;
    shifts_proposed += other.shifts_proposed;
    return *this;
  }
};

}  // namespace shapeproc::sample
