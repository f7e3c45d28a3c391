// Formats stage: the SVG reader's public face (include/casteljau/svg.hpp). A document is read and
// converted once into a display list (svg/convert.cpp and the per-feature files beside it), then
// drawn from that list (svg/draw.cpp) as often as asked, at any size. See svg.hpp for what is
// supported.
#include "casteljau/svg.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/paint.hpp"
#include "formats/svg/display_list.hpp"

namespace casteljau {

struct SvgDocument::Impl : svg::ConvertedDocument {};

SvgDocument::SvgDocument(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SvgDocument::SvgDocument(SvgDocument&&) noexcept = default;
SvgDocument& SvgDocument::operator=(SvgDocument&&) noexcept = default;
SvgDocument::~SvgDocument() = default;
int SvgDocument::width() const { return impl_->width; }
int SvgDocument::height() const { return impl_->height; }
double SvgDocument::intrinsic_width() const { return impl_->fwidth; }
double SvgDocument::intrinsic_height() const { return impl_->fheight; }
const std::vector<std::string>& SvgDocument::warnings() const { return impl_->warnings; }

SvgDocument SvgDocument::load(const std::string& path, const std::string& resource_root) {
    SvgOptions o;
    o.resource_root = resource_root;
    return load(path, o);
}

SvgDocument SvgDocument::load(const std::string& path, const SvgOptions& options) {
    enable_svg_glyphs();
    const std::vector<std::uint8_t> bytes = read_file(path);
    SvgOptions o = options;
    std::error_code ec;
    o.base_dir = std::filesystem::absolute(std::filesystem::path(path), ec).parent_path().string();
    auto impl = std::make_unique<Impl>();
    static_cast<svg::ConvertedDocument&>(*impl) =
        svg::convert_document(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), o, path);
    return SvgDocument(std::move(impl));
}

SvgDocument SvgDocument::parse(std::string_view input, const SvgOptions& options) {
    enable_svg_glyphs();
    auto impl = std::make_unique<Impl>();
    static_cast<svg::ConvertedDocument&>(*impl) = svg::convert_document(input, options);
    return SvgDocument(std::move(impl));
}

void SvgDocument::render(Canvas& canvas, const Affine& base) const { svg::draw(impl_->items, canvas, base); }

Pixmap SvgDocument::render() const { return render_size(impl_->width, impl_->height); }

Pixmap SvgDocument::render_size(int width, int height) const {
    Pixmap pm(width, height);
    Canvas c(pm);
    render(c, Affine::scale(width / impl_->fwidth, height / impl_->fheight));
    return pm;
}

std::pair<int, int> SvgDocument::output_size_for_width(int width) const {
    check_canvas_size(width, 1);
    const double h = std::ceil(static_cast<double>(width) * impl_->height / impl_->width);
    check_canvas_size(width, h);
    return {width, static_cast<int>(h)};
}

std::pair<int, int> SvgDocument::output_size_for_height(int height) const {
    check_canvas_size(1, height);
    const double w = std::ceil(static_cast<double>(height) * impl_->width / impl_->height);
    check_canvas_size(w, height);
    return {static_cast<int>(w), height};
}

std::pair<int, int> SvgDocument::output_size_for_zoom(double zoom) const {
    if (!(zoom > 0) || !std::isfinite(zoom)) throw Error(ErrorKind::InvalidArgument, "zoom must be positive");
    const double w = std::ceil(impl_->width * zoom), h = std::ceil(impl_->height * zoom);
    check_canvas_size(w, h);
    return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace casteljau
