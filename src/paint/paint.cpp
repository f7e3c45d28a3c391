// Paint stage: the Paint value (include/casteljau/paint.hpp).
#include "casteljau/paint.hpp"

#include <utility>

#include "casteljau/shader.hpp"

namespace casteljau {

Paint Paint::shaded(Shader s) {
    Paint p;
    p.shader = std::make_shared<const Shader>(std::move(s));
    return p;
}

}  // namespace casteljau
