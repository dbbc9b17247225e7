// viscoroll: the variable in which the line solver expands a(y) and b(y) (line_shape.hpp), a
// setting of LineOptions (line_options.hpp) in a header of its own, so that the options need
// nothing of the shape's numerics.
#pragma once

namespace viscoroll {

/// The variable in which a(y) and b(y) are expanded (w = 1 - t^2, s = sqrt(w)).
enum class LineBasis {
  t_squared,  ///< v = 1 - 2 w = 2 t^2 - 1
  s,          ///< v = 2 s - 1 (resolves odd powers of a ~ sqrt(1 - t^2) at the ends)
  /// v = 2 asinh(s/e)/asinh(1/e) - 1 with e = LineShape::scale = V tau/((1 + f) a_ref): resolves
  /// the layer at the ends of the slow regime, where G has poles at s = +-i j_{0,k} e a_ref/a_end
  /// (docs/theory.md section 10); tends to `s` as e grows.
  s_mapped,
};

}  // namespace viscoroll
