#pragma once
// Keeping the parts of a model file the core does not interpret (icons, notes, GUI
// settings), so that load -> save round-trips a model without losing them. The GUI layout
// is read into typed values as well (core/GuiLayout.h), each beside its element's XML.
#include <pugixml.hpp>

#include <string>

namespace tlmhub {
class Component;
class System;
}

namespace tlmhub::preserved {

// Children of a <component>/<system> element other than the ones the loader reads, and its layout.
void storeComponentExtras(Component& component, pugi::xml_node element);
// Children of the root <system> the loader does not read (hopsangui, ...), and its layout.
void storeSystemExtras(System& root, pugi::xml_node element);
// Children of <hopsanmodelfile> other than <system> (requirements, info) and its attributes.
void storeDocumentExtras(System& root, pugi::xml_node top);
// A system port's or connection's layout and children (System::systemPortExtras, connectionExtras).
void storeSystemPortExtras(System& system, const std::string& portName, pugi::xml_node element);
void storeConnectionExtras(System& system, const std::string& a, const std::string& pa,
                           const std::string& b, const std::string& pb, pugi::xml_node element);
void storeOtherObject(System& system, pugi::xml_node element);

std::string connectionKey(const std::string& a, const std::string& pa, const std::string& b,
                          const std::string& pb);
// The four names of a connectionKey; names are sanitised to [A-Za-z0-9_], so the
// separators '.' and '|' cannot occur inside them.
struct ConnectionKeyParts {
    std::string a, pa, b, pb;
};
ConnectionKeyParts parseConnectionKey(const std::string& key);
// Append the serialized children in `xml` to `parent`.
void appendFragment(pugi::xml_node parent, const std::string& xml);

} // namespace tlmhub::preserved
