#pragma once
// The typed GUI layout (core/GuiLayout.h) read from and written into a model file's elements.
// Reading never fails: missing or unreadable values read as the defaults. Writing changes
// only the attributes and elements whose values differ from what the element already says,
// and keeps every other child of <hopsangui> in its place.
#include "core/GuiLayout.h"

#include <pugixml.hpp>

namespace tlmhub::guixml {

// `element` is a <component>, <system> or <systemport>; the layout is in its <hopsangui>.
ObjectLayout readObjectLayout(pugi::xml_node element);
void writeObjectLayout(pugi::xml_node element, const ObjectLayout& layout);

// `connect` is a <connect> element. Writing new points also writes the <geometries> Hopsan
// derives from them.
ConnectionLayout readConnectionLayout(pugi::xml_node connect);
void writeConnectionLayout(pugi::xml_node connect, const ConnectionLayout& layout);

// `element` is the root <system>; its controls are in its <hopsangui>.
std::vector<LiveControlLayout> readLiveControls(pugi::xml_node element);
void writeLiveControls(pugi::xml_node element, const std::vector<LiveControlLayout>& controls);

} // namespace tlmhub::guixml
