#include "core/hmf/HmfLoader.h"

#include "core/FileAccess.h"

#include "core/ComponentFactory.h"
#include "core/hmf/LegacyNames.h"
#include "core/hmf/PreservedXml.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tlmhub {

bool LoadedModel::hasErrors() const
{
    for (const auto& m : messages)
        if (m.type == MessageType::Error || m.type == MessageType::Fatal) return true;
    return !root;
}

std::string LoadedModel::firstError() const
{
    for (const auto& m : messages)
        if (m.type == MessageType::Error || m.type == MessageType::Fatal) return m.text;
    return root ? std::string() : std::string("model could not be loaded");
}

Status LoadedModel::status() const
{
    for (const auto& m : messages)
        if (m.type == MessageType::Error || m.type == MessageType::Fatal)
            return {m.code == StatusCode::Ok ? StatusCode::InvalidModel : m.code, m.text, m.source};
    if (!root) return {StatusCode::InvalidModel, "model could not be loaded"};
    return Status::ok();
}

namespace {

class Loader {
public:
    Loader(std::string sourceName, std::string directory, const LoadLimits& limits,
           std::vector<Message>& messages)
        : mSource(std::move(sourceName)), mDirectory(std::move(directory)), mLimits(limits),
          mMessages(messages)
    {}

    std::unique_ptr<System> loadDocument(const pugi::xml_document& doc)
    {
        pugi::xml_node top = doc.child("hopsanmodelfile");
        if (!top) {
            error("the root element is not <hopsanmodelfile>");
            return nullptr;
        }
        mVersion.text = top.attribute("hopsancoreversion").as_string("0");
        pugi::xml_node sysNode = top.child("system");
        if (!sysNode) {
            error("<hopsanmodelfile> has no <system> element");
            return nullptr;
        }
        auto root = std::make_unique<System>();
        root->modelDirectory = mDirectory;
        pugi::xml_node simTime = sysNode.child("simulationtime");
        root->startTime = simTime.attribute("start").as_double(0.0);
        root->stopTime = simTime.attribute("stop").as_double(2.0);
        // Keep everything of the file the core does not interpret, for saving.
        preserved::storeDocumentExtras(*root, top);
        loadSystem(*root, sysNode, true);
        return root;
    }

private:
    void message(MessageType type, const std::string& text, StatusCode code = StatusCode::Ok)
    {
        mMessages.push_back({type, mSource + ": " + text, {}, {}, code});
    }
    void error(const std::string& text, StatusCode code = StatusCode::InvalidModel)
    {
        message(MessageType::Error, text, code);
    }
    void warning(const std::string& text) { message(MessageType::Warning, text); }

    static bool parseBool(const pugi::xml_attribute& a, bool def)
    {
        if (!a) return def;
        std::string v = a.as_string();
        return v == "true" || v == "1";
    }

    void loadSimulationSettings(System& sys, pugi::xml_node node, bool isRoot)
    {
        if (pugi::xml_node st = node.child("simulationtime")) {
            double ts = st.attribute("timestep").as_double(0.001);
            sys.desiredTimestep = ts;
            sys.mTimestep = ts;
            sys.inheritTimestep = parseBool(st.attribute("inherit_timestep"), true);
            if (isRoot) sys.inheritTimestep = false;
        }
        if (pugi::xml_node ls = node.child("simulationlogsettings")) {
            if (ls.attribute("numsamples")) sys.requestedLogSamples = ls.attribute("numsamples").as_ullong(0);
            sys.logStartTime = ls.attribute("starttime").as_double(0.0);
        } else if (node.attribute("logsamples")) {
            sys.requestedLogSamples = node.attribute("logsamples").as_ullong(0);
        }
    }

    void loadSystemParameters(System& sys, pugi::xml_node node)
    {
        for (pugi::xml_node p : node.child("parameters").children("parameter")) {
            std::string name = p.attribute("name").as_string();
            std::string value = p.attribute("value").as_string();
            std::string type = p.attribute("type").as_string("double");
            std::string unit = p.attribute("unit").as_string(p.attribute("quantity").as_string());
            const Status set = sys.setSystemParameter(name, value, type, p.attribute("description").as_string(),
                                                      unit, parseBool(p.attribute("internal"), false));
            if (!set) warning("system '" + sys.name() + "', parameter '" + name + "': " + set.message());
        }
    }

    // False if the component has no such parameter (yet: an external definition may add it).
    bool trySetComponentParameter(Component& comp, const std::string& rawName, const std::string& value,
                                  const std::string& originalType)
    {
        std::string name = legacy::currentParameterName(originalType, rawName, mVersion);
        Parameter* p = comp.parameters().find(name);
        if (!p && name.find('#') == std::string::npos) p = comp.parameters().find(name + "#Value");
        if (!p) return false;
        p->value = value;
        return true;
    }

    void setComponentParameter(Component& comp, const std::string& rawName, const std::string& value,
                               const std::string& originalType)
    {
        if (!trySetComponentParameter(comp, rawName, value, originalType))
            warning("component '" + comp.name() + "' (" + comp.typeName() + ") has no parameter '" +
                    rawName + "'; ignored, the default is kept");
    }

    // Counts one more component or subsystem; false (with the error) past the limit.
    bool admitComponent()
    {
        ++mComponentCount;
        if (mLimits.maxComponents == 0 || mComponentCount <= mLimits.maxComponents) return true;
        error("the model has more than " + std::to_string(mLimits.maxComponents) +
              " components and subsystems, the limit here" + mLimits.componentsHint);
        mFailed = true;
        return false;
    }

    void loadComponent(System& sys, pugi::xml_node node)
    {
        if (!admitComponent()) return;
        const std::string originalType = node.attribute("typename").as_string();
        const std::string type = legacy::currentTypeName(originalType);
        std::unique_ptr<Component> comp = ComponentFactory::instance().create(type);
        if (!comp) {
            error("component '" + std::string(node.attribute("name").as_string()) + "' in system '" +
                      sys.name() + "': unknown component type '" + originalType + "'",
                  StatusCode::UnknownComponentType);
            mFailed = true;
            return;
        }
        comp->setNameRaw(sanitizeName(node.attribute("name").as_string()));
        comp->setSubTypeName(node.attribute("subtypename").as_string());
        comp->setDisabled(parseBool(node.attribute("disabled"), false));
        preserved::storeComponentExtras(*comp, node);
        const std::string desired = comp->name();
        Component* raw = comp.get();
        const std::string actual = sys.addComponent(std::move(comp));
        if (actual != desired) mRenames[&sys][desired] = actual;
        // Parameters the component lacks may come with its external definition: set them
        // after loading it.
        std::vector<std::pair<std::string, std::string>> later;
        for (pugi::xml_node p : node.child("parameters").children("parameter"))
            if (!trySetComponentParameter(*raw, p.attribute("name").as_string(), p.attribute("value").as_string(),
                                          originalType))
                later.emplace_back(p.attribute("name").as_string(), p.attribute("value").as_string());
        for (pugi::xml_node sv : node.child("startvalues").children("startvalue")) {
            std::string pname = std::string(sv.attribute("portname").as_string()) + "#" +
                                sv.attribute("variable").as_string();
            if (!trySetComponentParameter(*raw, pname, sv.attribute("value").as_string(), originalType))
                later.emplace_back(pname, sv.attribute("value").as_string());
        }
        if (raw->loadsExternalDefinition() && mLimits.maxExternalDefinitions &&
            ++mExternalDefinitionCount > mLimits.maxExternalDefinitions) {
            error("the model has more than " + std::to_string(mLimits.maxExternalDefinitions) + " " + raw->typeName() +
                      " components (each loads a file), the limit here" + mLimits.externalDefinitionsHint,
                  StatusCode::InvalidModel);
            mFailed = true;
            return;
        }
        if (const Status loaded = raw->loadExternalDefinition(); !loaded)
            error("component '" + raw->name() + "' (" + raw->typeName() + "): " + loaded.message(),
                  loaded.code());
        for (const auto& [name, value] : later) setComponentParameter(*raw, name, value, originalType);
        for (pugi::xml_node port : node.child("ports").children("port")) {
            if (pugi::xml_attribute q = port.attribute("signalquantity")) {
                std::string pn = legacy::currentPortName(type, port.attribute("name").as_string(),
                                                         mVersion.refusedByHopsanCore());
                if (Port* p = raw->port(pn)) {
                    p->signalQuantity = q.as_string();
                    if (p->node()) p->node()->signalQuantity = q.as_string();
                }
            }
        }
    }

    void loadSubsystem(System& parent, pugi::xml_node node, std::size_t depth)
    {
        if (!admitComponent()) return;
        if (depth > mLimits.maxSubsystemDepth) {
            error("subsystem '" + std::string(node.attribute("name").as_string()) + "' is nested " +
                  std::to_string(depth) + " levels deep; the limit is " +
                  std::to_string(mLimits.maxSubsystemDepth) + mLimits.depthHint);
            mFailed = true;
            return;
        }
        std::unique_ptr<System> sub;
        const std::string external = node.attribute("external_path").as_string();
        if (!external.empty()) {
            namespace fs = std::filesystem;
            if (!modelFileAccessAllowed()) {
                error("external subsystem '" + std::string(node.attribute("name").as_string()) +
                      "' (" + external + "): loading files is disabled for models on this server");
                mFailed = true;
                return;
            }
            fs::path p = fs::path(mDirectory) / external;
            // The file's own subsystems count from this depth (a file that includes itself
            // ends at the limit instead of recursing for ever).
            LoadLimits nested = mLimits;
            nested.maxSubsystemDepth = mLimits.maxSubsystemDepth - depth;
            LoadedModel loaded = loadHmfFile(p.string(), nested);
            for (auto& m : loaded.messages) mMessages.push_back(m);
            if (!loaded.root) {
                error("external subsystem '" + std::string(node.attribute("name").as_string()) +
                      "' (" + external + ") could not be loaded");
                mFailed = true;
                return;
            }
            sub = std::move(loaded.root);
            sub->externalPath = external;
            sub->setNameRaw(sanitizeName(node.attribute("name").as_string()));
            System* raw = sub.get();
            parent.addComponent(std::move(sub));
            loadSystemParameters(*raw, node);
            return;
        }
        sub = std::make_unique<System>();
        if (std::string(node.attribute("typename").as_string()) == "ConditionalSubsystem") sub->makeConditional();
        sub->setNameRaw(sanitizeName(node.attribute("name").as_string()));
        sub->setDisabled(parseBool(node.attribute("disabled"), false));
        System* raw = sub.get();
        const std::string desired = raw->name();
        const std::string actual = parent.addComponent(std::move(sub));
        if (actual != desired) mRenames[&parent][desired] = actual;
        loadSystem(*raw, node, false, depth);
    }

    void loadSystem(System& sys, pugi::xml_node node, bool isRoot, std::size_t depth = 0)
    {
        if (isRoot) sys.setNameRaw(sanitizeName(node.attribute("name").as_string()));
        sys.setSubTypeName(node.attribute("subtypename").as_string());
        loadSimulationSettings(sys, node, isRoot);
        loadSystemParameters(sys, node);
        if (!isRoot) preserved::storeComponentExtras(sys, node);
        else preserved::storeSystemExtras(sys, node);

        for (pugi::xml_node child : node.child("objects").children()) {
            const std::string tag = child.name();
            if (tag == "component") {
                loadComponent(sys, child);
            } else if (tag == "system") {
                std::string t = child.attribute("typename").as_string("Subsystem");
                if (!child.attribute("external_path") && t != "Subsystem" && t != "ConditionalSubsystem") {
                    warning("system '" + std::string(child.attribute("name").as_string()) +
                            "' has type '" + t + "'; the rest of system '" + sys.name() + "' is not loaded");
                    return;
                }
                loadSubsystem(sys, child, depth + 1);
                if (mFailed) return;
            } else if (tag == "systemport") {
                Port* p = sys.addSystemPort(sanitizeName(child.attribute("name").as_string()));
                preserved::storeSystemPortExtras(sys, p->name(), child);
            } else {
                preserved::storeOtherObject(sys, child);
            }
        }
        const bool fullRenames = mVersion.refusedByHopsanCore();
        for (pugi::xml_node c : node.child("connections").children("connect")) {
            std::string a = resolveName(sys, sanitizeName(c.attribute("startcomponent").as_string()));
            std::string b = resolveName(sys, sanitizeName(c.attribute("endcomponent").as_string()));
            std::string pa = sanitizeName(c.attribute("startport").as_string());
            std::string pb = sanitizeName(c.attribute("endport").as_string());
            if (Component* ca = sys.component(a)) pa = legacy::currentPortName(ca->typeName(), pa, fullRenames);
            if (Component* cb = sys.component(b)) pb = legacy::currentPortName(cb->typeName(), pb, fullRenames);
            if (const Status connected = sys.connect(a, pa, b, pb); !connected) {
                error("system '" + sys.name() + "', <connect> " + a + "." + pa + " - " + b + "." + pb +
                      ": " + connected.message());
            } else {
                preserved::storeConnectionExtras(sys, a, pa, b, pb, c);
            }
        }
        // Again: start values of C-type subsystem ports exist only after connecting.
        loadSystemParameters(sys, node);
        for (pugi::xml_node al : node.child("aliases").children("alias")) {
            std::string name = al.attribute("name").as_string();
            std::string full = al.child_value("fullname");
            if (!name.empty()) sys.aliases[name] = full;
        }
    }

    std::string resolveName(System& sys, const std::string& name)
    {
        auto it = mRenames.find(&sys);
        if (it != mRenames.end()) {
            auto jt = it->second.find(name);
            if (jt != it->second.end()) return jt->second;
        }
        return name;
    }

    std::string mSource;
    std::string mDirectory;
    LoadLimits mLimits;
    std::vector<Message>& mMessages;
    std::size_t mComponentCount = 0;
    std::size_t mExternalDefinitionCount = 0;
    legacy::CoreVersion mVersion;
    std::map<System*, std::map<std::string, std::string>> mRenames;

public:
    bool mFailed = false;
};

// Deepest element nesting, found without recursion (pugixml's traversal keeps its own stack).
std::size_t xmlDepth(const pugi::xml_document& doc, std::size_t stopAbove)
{
    struct DepthWalker : pugi::xml_tree_walker {
        std::size_t deepest = 0;
        std::size_t stopAbove = 0;
        bool for_each(pugi::xml_node&) override
        {
            deepest = std::max(deepest, static_cast<std::size_t>(depth()) + 1);
            return deepest <= stopAbove;
        }
    } walker;
    walker.stopAbove = stopAbove;
    const_cast<pugi::xml_document&>(doc).traverse(walker);
    return walker.deepest;
}

} // namespace

LoadedModel loadHmfString(const std::string& xml, const std::string& modelDirectory,
                          const std::string& sourceName, const LoadLimits& limits)
{
    LoadedModel result;
    pugi::xml_document doc;
    pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size());
    if (!parsed) {
        std::ostringstream os;
        os << sourceName << ": broken XML at byte " << parsed.offset << ": " << parsed.description();
        result.messages.push_back({MessageType::Error, os.str(), {}});
        return result;
    }
    if (xmlDepth(doc, kMaxXmlDepth) > kMaxXmlDepth) {
        result.messages.push_back({MessageType::Error,
                                   sourceName + ": XML elements are nested more than " +
                                       std::to_string(kMaxXmlDepth) + " levels deep",
                                   {}});
        return result;
    }
    Loader loader(sourceName, modelDirectory, limits, result.messages);
    result.root = loader.loadDocument(doc);
    if (loader.mFailed) result.root.reset();
    return result;
}

LoadedModel loadHmfFile(const std::string& path, const LoadLimits& limits)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        LoadedModel result;
        result.messages.push_back({MessageType::Error, path + ": cannot open the file", {}, {}, StatusCode::IoError});
        return result;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    namespace fs = std::filesystem;
    std::string dir = fs::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
    return loadHmfString(ss.str(), dir, path, limits);
}

} // namespace tlmhub
