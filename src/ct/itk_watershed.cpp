// Distance-transform watershed with ITK, behind itk_bridge.h.
//
// Touching grains form one solid blob in the thresholded mask. Inside the
// solid, the Euclidean distance to the nearest pore, d(x), has one hill per
// grain (its top near the grain's centre) and a saddle at each neck where
// grains touch. Noise and facets add small spurious hills. h-maxima (the
// morphological reconstruction by dilation of d - h under d) removes every
// hill that rises less than h above its saddle, so each remaining regional
// maximum marks one grain; the marker watershed of -d then floods from those
// markers and the basins meet at the necks. Two touching grains stay apart
// when each rises more than h above the neck: min(r_a, r_b) - r_neck > h,
// with r the largest inscribed radius; a grain's own lobes (a dented grain)
// stay together when their saddle is within h of the lower top.
#include "ct/itk_bridge.h"

#include "core/error.h"

#include <itkConnectedComponentImageFilter.h>
#include <itkHMaximaImageFilter.h>
#include <itkImage.h>
#include <itkMorphologicalWatershedFromMarkersImageFilter.h>
#include <itkRegionalMaximaImageFilter.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>

#include <algorithm>

namespace grainlab::ct::itk_bridge {

namespace {

using MaskImage = itk::Image<std::uint8_t, 3>;
using FloatImage = itk::Image<float, 3>;
using LabelImage = itk::Image<std::uint32_t, 3>;

template <typename Image>
typename Image::Pointer make_image(const std::array<std::int64_t, 3>& size) {
  auto image = Image::New();
  typename Image::SizeType s;
  for (unsigned a = 0; a < 3; ++a) s[a] = static_cast<itk::SizeValueType>(size[a]);
  image->SetRegions(s);
  image->Allocate();
  return image;
}

// Forwards an ITK filter's progress into [from, to] of the whole.
void watch(itk::Object* filter, const ProgressFn& progress, double from, double to) {
  if (!progress) return;
  auto* process = dynamic_cast<itk::ProcessObject*>(filter);
  filter->AddObserver(itk::ProgressEvent(), [process, progress, from, to](const itk::EventObject&) {
    progress(from + (to - from) * process->GetProgress());
  });
}

// Labels 1..count on the regional maxima of the h-maxima reconstruction of
// `height` (one per hill rising more than h above its saddle), 0 elsewhere.
struct Markers {
  LabelImage::Pointer image;
  std::uint32_t count = 0;
};
Markers markers_at(const FloatImage::Pointer& height, double h, const ProgressFn& progress, double from, double to) {
  auto hmax = itk::HMaximaImageFilter<FloatImage, FloatImage>::New();
  hmax->SetInput(height);
  hmax->SetHeight(static_cast<float>(h));
  hmax->SetFullyConnected(true);
  watch(hmax, progress, from, to);
  auto peaks = itk::RegionalMaximaImageFilter<FloatImage, MaskImage>::New();
  peaks->SetInput(hmax->GetOutput());
  peaks->SetFullyConnected(true);
  peaks->SetForegroundValue(1);
  peaks->SetBackgroundValue(0);
  peaks->SetFlatIsMaxima(false);
  auto label = itk::ConnectedComponentImageFilter<MaskImage, LabelImage>::New();
  label->SetInput(peaks->GetOutput());
  label->SetFullyConnected(true);
  label->Update();
  Markers m{label->GetOutput(), static_cast<std::uint32_t>(label->GetObjectCount())};
  m.image->DisconnectPipeline();
  return m;
}

// The median over markers of the highest `height` on each (a hill's top:
// inscribed radius + 1 voxel, see below), minus the 1.
double median_top(const Markers& m, const FloatImage::Pointer& height) {
  std::vector<float> top(m.count + 1, 0.0f);
  const std::uint32_t* mk = m.image->GetBufferPointer();
  const float* d = height->GetBufferPointer();
  const std::size_t n = height->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    if (mk[i]) top[mk[i]] = std::max(top[mk[i]], d[i]);
  top.erase(top.begin());
  if (top.empty()) return 0;
  std::nth_element(top.begin(), top.begin() + top.size() / 2, top.end());
  return std::max(0.0, top[top.size() / 2] - 1.0);
}

}  // namespace

Watershed distance_watershed(const std::vector<std::uint8_t>& mask, const std::array<std::int64_t, 3>& size, double h,
                             const ProgressFn& progress) {
  const std::size_t n = mask.size();
  try {
    // Distance inside the solid (voxels), shifted so that every solid voxel is >= 1 and pores are 0.
    FloatImage::Pointer height;
    {
      auto m = make_image<MaskImage>(size);
      std::copy(mask.begin(), mask.end(), m->GetBufferPointer());
      auto dist = itk::SignedMaurerDistanceMapImageFilter<MaskImage, FloatImage>::New();
      dist->SetInput(m);
      dist->SetBackgroundValue(0);
      dist->SetInsideIsPositive(true);
      dist->SetSquaredDistance(false);
      dist->SetUseImageSpacing(false);
      watch(dist, progress, 0.0, 0.25);
      dist->Update();
      height = dist->GetOutput();
      height->DisconnectPipeline();
      float* d = height->GetBufferPointer();
      for (std::size_t i = 0; i < n; ++i) d[i] = mask[i] ? std::max(d[i], 0.0f) + 1.0f : 0.0f;
    }

    // Markers: regional maxima of the h-maxima reconstruction, one label each
    // (for h = 0, first at the smallest depth to measure the grains' radii).
    Watershed result;
    Markers markers;
    if (h > 0) {
      result.h = h;
      markers = markers_at(height, h, progress, 0.25, 0.55);
    } else {
      markers = markers_at(height, kMinDepth, progress, 0.25, 0.4);
      result.typical_radius = median_top(markers, height);
      result.h = std::max(kMinDepth, kDepthPerRadius * result.typical_radius);
      if (result.h > kMinDepth) markers = markers_at(height, result.h, progress, 0.4, 0.55);
    }
    std::uint32_t marker_count = markers.count;
    std::uint32_t* mk = markers.image->GetBufferPointer();
    for (std::size_t i = 0; i < n; ++i) {
      if (!mask[i]) mk[i] = 0;
    }

    // A solid component without a marker (lower than h everywhere) gets one at its highest voxel.
    {
      auto m = make_image<MaskImage>(size);
      std::copy(mask.begin(), mask.end(), m->GetBufferPointer());
      auto comps = itk::ConnectedComponentImageFilter<MaskImage, LabelImage>::New();
      comps->SetInput(m);
      comps->SetFullyConnected(true);
      comps->Update();
      const std::uint32_t* c = comps->GetOutput()->GetBufferPointer();
      const std::size_t count = comps->GetObjectCount();
      std::vector<char> marked(count + 1, 0);
      std::vector<std::size_t> top(count + 1, n);
      const float* d = height->GetBufferPointer();
      for (std::size_t i = 0; i < n; ++i) {
        if (!c[i]) continue;
        if (mk[i]) marked[c[i]] = 1;
        if (top[c[i]] == n || d[i] > d[top[c[i]]]) top[c[i]] = i;
      }
      for (std::size_t k = 1; k <= count; ++k) {
        if (!marked[k]) mk[top[k]] = ++marker_count;
      }
    }

    // Flood -distance from the markers; pores (height 0) are flooded last and cleared after.
    float* d = height->GetBufferPointer();
    for (std::size_t i = 0; i < n; ++i) d[i] = -d[i];
    auto ws = itk::MorphologicalWatershedFromMarkersImageFilter<FloatImage, LabelImage>::New();
    ws->SetInput(height);
    ws->SetMarkerImage(markers.image);
    ws->SetMarkWatershedLine(false);
    ws->SetFullyConnected(true);
    watch(ws, progress, 0.55, 1.0);
    ws->Update();
    const std::uint32_t* out = ws->GetOutput()->GetBufferPointer();
    result.labels.resize(n);
    for (std::size_t i = 0; i < n; ++i) result.labels[i] = mask[i] ? out[i] : 0;
    return result;
  } catch (const itk::ExceptionObject& e) {
    throw RunError(fmt::format("the watershed failed inside ITK: {}", e.GetDescription()));
  } catch (const std::bad_alloc&) {
    throw RunError("out of memory in the watershed: crop the volume or use a machine with more memory");
  }
}

}  // namespace grainlab::ct::itk_bridge
