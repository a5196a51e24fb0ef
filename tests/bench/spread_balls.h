#pragma once
// The fourteen object balls other than the 5, spread over the table with none near the line from
// (0.3, -0.2) past the 5 at (0.7, 0.1) into the top-right corner: the full table of the aim and shots
// benchmarks, as `ball` lines.
#include <cstdio>
#include <string>

namespace bsim::bench {

inline std::string spread_ball_lines() {
  const double spots[14][2] = {{-1.0, 0.4},  {-1.0, 0.0}, {-1.0, -0.4},  {-0.7, 0.2},  {-0.7, -0.2},
                               {-0.4, 0.45}, {-0.4, 0.0}, {-0.4, -0.45}, {-0.1, 0.25}, {-0.1, -0.3},
                               {0.2, 0.45},  {0.5, -0.5}, {1.0, -0.2},   {1.1, -0.5}};
  const int numbers[14] = {1, 2, 3, 4, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  std::string text;
  for (int k = 0; k < 14; ++k) {
    char line[96];
    std::snprintf(line, sizeof line, "ball %d %.3f %.3f 0.028575 0 0 0 1 0 0 0\n", numbers[k], spots[k][0],
                  spots[k][1]);
    text += line;
  }
  return text;
}

}  // namespace bsim::bench
