#pragma once
#include <string>

#include <Eigen/Core>

namespace hdprior::render {

// What a layer tells the view's overlay about how to read it (see render/overlays/).

// A colour map over a value range: drawn as a colour bar with the range's end values.
struct ColourScale {
  std::string title;        // what the colour shows, e.g. "NDT score"
  double low = 0.0, high = 1.0;
  std::string unit;         // appended to the end values ("m"); empty when the value has none
  bool openHigh = false;    // values above `high` get the top colour: its label reads "high+"
  Eigen::Vector3f (*map)(float) = nullptr;  // a function of render/colormap.h, t in [0, 1]

  bool operator==(const ColourScale& o) const {
    return title == o.title && low == o.low && high == o.high && unit == o.unit && map == o.map;
  }
};

// One kind of marker a layer draws (a dot with a heading tick), named in the view's legend.
struct MarkerKey {
  std::string name;
  Eigen::Vector4f colour;
};

}  // namespace hdprior::render
