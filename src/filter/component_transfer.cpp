// Filter stage: feComponentTransfer. Each channel of the straight (unpremultiplied) colour goes
// through its transfer function (identity, table, discrete, linear, gamma, as the SVG
// specification defines them); results are clamped to [0, 1] and premultiplied again.
#include "filter/image.hpp"

namespace casteljau::filter {

double TransferFunction::apply(double c) const {
    switch (type) {
        case Identity: return c;
        case Table: {
            const std::size_t n = table.size();
            if (n == 0) return c;
            if (n == 1) return table[0];
            const double pos = std::clamp(c, 0.0, 1.0) * static_cast<double>(n - 1);
            const std::size_t k = std::min(static_cast<std::size_t>(pos), n - 2);
            return table[k] + (pos - static_cast<double>(k)) * (table[k + 1] - table[k]);
        }
        case Discrete: {
            const std::size_t n = table.size();
            if (n == 0) return c;
            const std::size_t k =
                std::min(static_cast<std::size_t>(std::clamp(c, 0.0, 1.0) * static_cast<double>(n)), n - 1);
            return table[k];
        }
        case Linear: return slope * c + intercept;
        case Gamma: return amplitude * std::pow(c, exponent) + offset;
    }
    return c;
}

namespace detail {

void component_transfer(Img& img, const std::array<TransferFunction, 4>& f) {
    for_each_straight(img, [&f](double c[4]) {
        for (std::size_t k = 0; k < 4; ++k)
            if (f[k].type != TransferFunction::Identity) c[k] = f[k].apply(c[k]);
    });
}

}  // namespace detail
}  // namespace casteljau::filter
