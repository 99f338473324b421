// filter_table.cpp: the rows of the filter table, one library call each.
#include "filter_table.h"

#include <mcdenoise/mcdenoise.h>

namespace testfilters {

namespace {

/// A guide of a GuideSet that is a field of the library's `Guides`.
struct HeldGuide {
    const char* field;  ///< the field's name in mcdenoise::guide_fields
    GuideBit bit;
    ImageBuf GuideSet::*image;
};

/// The GuideSet guides the feature filters may use.
constexpr HeldGuide held_guides[] = {
    { "object_id", needs_id, &GuideSet::object_id }, { "normal", needs_normal, &GuideSet::normal },
    { "depth", needs_depth, &GuideSet::depth },       { "albedo", needs_albedo, &GuideSet::albedo },
    { "variance", needs_variance, &GuideSet::variance },
};

/// The feature filters' view of `g`: every guide that is there.
mcdenoise::Guides features(const GuideSet& g)
{
    mcdenoise::Guides f;
    for (const HeldGuide& held : held_guides)
        for (const mcdenoise::GuideField& field : mcdenoise::guide_fields)
            if (field.bit == mcdenoise::guide_bit(held.field) && (g.*held.image).initialized())
                f.*field.member = &(g.*held.image);
    return f;
}

/// The GuideBit flags of the guides in the library's `used` that a GuideSet
/// holds.
unsigned needs(mcdenoise::GuideMask used)
{
    unsigned bits = 0;
    for (const HeldGuide& held : held_guides)
        if (used & mcdenoise::guide_bit(held.field))
            bits |= held.bit;
    return bits;
}

}  // namespace

const std::vector<FilterRow>& filter_table()
{
    static const std::vector<FilterRow> table = {
        { "mean", 0,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet&, int s, ROI r, int n) {
              return mcdenoise::mean(d, b, s, r, n);
          } },
        { "median", 0,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet&, int s, ROI r, int n) {
              return mcdenoise::median(d, b, s, r, n);
          } },
        { "gaussian", 0,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet&, int s, ROI r, int n) {
              return mcdenoise::gaussian(d, b, s, r, n);
          } },
        { "object_mean", needs_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::object_mean(d, b, g.object_id, s, r, n);
          } },
        { "object_median", needs_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::object_median(d, b, g.object_id, s, r, n);
          } },
        { "object_gaussian", needs_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::object_gaussian(d, b, g.object_id, s, r, n);
          } },
        { "brdf_mean", needs_id | needs_reflect_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::brdf_mean(d, b, g.object_id, g.reflect_id, s, r, n);
          } },
        { "brdf_gaussian", needs_id | needs_reflect_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::brdf_gaussian(d, b, g.object_id, g.reflect_id, s, r, n);
          } },
        { "brdf_median", needs_id | needs_reflect_id,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::brdf_median(d, b, g.object_id, g.reflect_id, s, r, n);
          } },
        { "normal_mean", needs_id | needs_normal,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::normal_mean(d, b, g.object_id, g.normal, s, r, n);
          } },
        { "normal_gaussian", needs_id | needs_normal,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::normal_gaussian(d, b, g.object_id, g.normal, s, r, n);
          } },
        { "dof", needs_id | needs_depth,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::dof(d, b, g.object_id, g.depth, s, s / 2, mcdenoise::dof_image_depth_range,
                                    mcdenoise::dof_image_depth_range, r, n);
          } },
        { "cross_bilateral", needs(mcdenoise::cross_bilateral_guides),
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::cross_bilateral(d, b, features(g), s,
                                                mcdenoise::default_cross_bilateral_sigma_spatial,
                                                mcdenoise::default_cross_bilateral_sigma_color, {}, r, n);
          } },
        { "atrous", needs(mcdenoise::atrous_guides),
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::atrous(d, b, features(g), s / 2, mcdenoise::default_atrous_sigma_luminance, {}, r,
                                       n);
          } },
        { "nlmeans", needs(mcdenoise::nlmeans_guides),
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::nlmeans(d, b, features(g), s / 2, mcdenoise::default_nlmeans_patch_radius,
                                        mcdenoise::default_nlmeans_strength, {}, r, n);
          } },
        { "clamp_fireflies", needs(mcdenoise::clamp_fireflies_guides),
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int s, ROI r, int n) {
              return mcdenoise::clamp_fireflies(d, b, features(g), mcdenoise::default_firefly_factor, s / 2, r,
                                                n);
          },
          true },
        { "demodulate", needs_albedo,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int, ROI r, int n) {
              return mcdenoise::demodulate(d, b, g.albedo, mcdenoise::default_demodulate_epsilon, r, n);
          },
          true },
        { "remodulate", needs_albedo,
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int, ROI r, int n) {
              return mcdenoise::remodulate(d, b, g.albedo, mcdenoise::default_demodulate_epsilon, r, n);
          },
          true },
        { "denoise", needs(mcdenoise::denoise_guides),
          [](ImageBuf& d, const ImageBuf& b, const GuideSet& g, int, ROI r, int n) {
              return mcdenoise::denoise(d, b, features(g), r, n);
          } },
    };
    return table;
}

int guide_channels(GuideBit guide)
{
    return guide == needs_normal || guide == needs_albedo || guide == needs_variance ? 3 : 1;
}

std::vector<FilterRow> filter_rows(bool (*keep)(const FilterRow&))
{
    std::vector<FilterRow> rows;
    for (const FilterRow& row : filter_table())
        if (keep(row))
            rows.push_back(row);
    return rows;
}

}  // namespace testfilters
