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
            const std::size_t k = std::min(static_cast<std::size_t>(std::clamp(c, 0.0, 1.0) * static_cast<double>(n)), n - 1);
            return table[k];
        }
        case Linear: return slope * c + intercept;
        case Gamma: return amplitude * std::pow(c, exponent) + offset;
    }
    return c;
}

namespace detail {

void component_transfer(Img& img, const std::array<TransferFunction, 4>& f) {
    float* p = img.px.data();
    for (std::size_t i = 0, n = img.count(); i < n; ++i, p += 4) {
        const double a = p[3];
        double c[4] = {0, 0, 0, a};
        if (a > 0)
            for (int k = 0; k < 3; ++k) c[k] = std::min(1.0, p[k] / a);
        for (int k = 0; k < 4; ++k)
            if (f[static_cast<std::size_t>(k)].type != TransferFunction::Identity)
                c[k] = std::clamp(f[static_cast<std::size_t>(k)].apply(c[k]), 0.0, 1.0);
        for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(c[k] * c[3]);
        p[3] = static_cast<float>(c[3]);
    }
}

}  // namespace detail
}  // namespace casteljau::filter
