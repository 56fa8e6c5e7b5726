// The checked input of one analysis without a copy of the scan: prepare_input copies the scan's arrays even
// where it removed nothing (a 50 x 50 m floor's are 21 MB); an analysis reads them in place instead.
#pragma once
#include "roomsense/input.h"

#include <span>

namespace roomsense::detail {

struct InputView {
  InputView() = default;
  InputView(const InputView&) = delete;  // the views may point into `checked`
  InputView& operator=(const InputView&) = delete;
  InputView(InputView&&) = default;  // moving keeps the arrays' storage, so the views stay valid

  PreparedInput checked;  // every count and the bounds; the arrays only where something was removed
  std::span<const glm::vec3> vertices;  // the scan's own arrays, or `checked`'s where something was removed
  std::span<const std::uint32_t> indices;
};

// prepare_input's checks and errors; the views are valid while `scan` and the result live.
InputView view_input(const Scan& scan, bool reject_outliers);

}  // namespace roomsense::detail
