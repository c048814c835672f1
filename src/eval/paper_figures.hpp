#pragma once

#include <array>
#include <string_view>

namespace shelfdock::eval {

/// What the paper reports in section 4, to print beside our figures.
struct PaperTable1Row {
  std::string_view model;  ///< our name for the model (config/models.yaml)
  double fitted_length_m;
  double fitted_width_m;
  double length_error;  ///< [-] as printed (0.3 % = 0.003)
  double width_error;   ///< [-]
};

/// The paper's Table 1: fitted length and width and their errors per model.
inline constexpr std::array<PaperTable1Row, 4> kPaperTable1 = {{
    {"t1-round-900x810", 0.903, 0.8239, 0.003, 0.017},
    {"t1-rect-1075x883", 1.0801, 0.9194, 0.0047, 0.041},
    {"t1-rect-1250x1250", 1.2569, 1.2859, 0.0055, 0.023},
    {"t1-rect-1080x856", 1.1122, 0.8452, 0.03, 0.013},
}};

/// Fig. 7: fluctuation of ten recognitions during one docking [m, m, rad].
inline constexpr double kPaperFluctuationX = 0.0119;
inline constexpr double kPaperFluctuationY = 0.0010;
inline constexpr double kPaperFluctuationYaw = 0.0081;
/// Fig. 8: docking errors "within 1 cm and 0.014 rad".
inline constexpr double kPaperDockingErrorXY = 0.01;
inline constexpr double kPaperDockingErrorYaw = 0.014;
/// Time over the 4.5 m docking area at 0.4 m/s, shelf 2 [s].
inline constexpr double kPaperContinuousTime = 11.21;
inline constexpr double kPaperStopTime = 15.138;
inline constexpr double kPaperTimeSaving = 0.259;

}  // namespace shelfdock::eval
