#include "server/protocol/SchemaValidator.h"

#include "server/protocol/EmbeddedProtocol.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <stdexcept>

namespace tlmhub::server {

namespace {

using nlohmann::json;

// Deeper than any real schema; stops a $ref cycle from recursing forever.
constexpr int kMaxDepth = 100;

const std::set<std::string>& knownKeywords()
{
    static const std::set<std::string> keys = {
        "$schema", "$id", "$defs", "$ref", "title", "description", "$comment", "examples",
        "type", "enum", "const", "oneOf", "anyOf", "properties", "required",
        "additionalProperties", "items", "minItems", "maxItems", "minimum", "maximum",
        "exclusiveMinimum", "minLength", "maxLength", "pattern"};
    return keys;
}

const std::set<std::string>& typeNames()
{
    static const std::set<std::string> names = {"null", "boolean", "object", "array",
                                                "number", "integer", "string"};
    return names;
}

bool isIdentifier(const std::string& key)
{
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

std::string childPath(const std::string& path, const std::string& key)
{
    if (isIdentifier(key)) return path + "." + key;
    return path + "[" + json(key).dump() + "]";
}

std::string indexPath(const std::string& path, std::size_t index)
{
    return path + "[" + std::to_string(index) + "]";
}

std::string pointerToken(const std::string& key)
{
    std::string out;
    for (char c : key) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

bool isInteger(const json& value)
{
    if (value.is_number_integer()) return true;
    if (!value.is_number_float()) return false;
    const double d = value.get<double>();
    return std::isfinite(d) && std::floor(d) == d;
}

bool hasType(const std::string& name, const json& value)
{
    if (name == "null") return value.is_null();
    if (name == "boolean") return value.is_boolean();
    if (name == "object") return value.is_object();
    if (name == "array") return value.is_array();
    if (name == "number") return value.is_number();
    if (name == "integer") return isInteger(value);
    if (name == "string") return value.is_string();
    return false;
}

// The JSON type name a value would be reported as ("got string").
std::string typeOf(const json& value)
{
    if (value.is_number()) return isInteger(value) ? "integer" : "number";
    return value.type_name();
}

std::size_t codePoints(const std::string& s)
{
    // Count every byte that does not continue a UTF-8 sequence.
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

// Short rendering of a JSON value for messages (long values are cut).
std::string shortDump(const json& value)
{
    std::string s = value.dump();
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    return s;
}

} // namespace

// ---------------------------------------------------------------- setup

const SchemaValidator& SchemaValidator::protocol()
{
    static const SchemaValidator instance = [] {
        SchemaValidator v;
        std::vector<const EmbeddedFile*> files;
        for (const EmbeddedFile& f : embeddedProtocolFiles()) {
            const std::string suffix = ".schema.json";
            if (f.name.size() > suffix.size() &&
                f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0)
                files.push_back(&f);
        }
        // messages.schema.json first: it holds x-requests and is the default document.
        std::stable_partition(files.begin(), files.end(),
                              [](const EmbeddedFile* f) { return f->name == "messages.schema.json"; });
        for (const EmbeddedFile* f : files) {
            json doc = json::parse(f->content, nullptr, false);
            std::string error;
            if (doc.is_discarded() || !v.addDocument(std::move(doc), error))
                throw std::logic_error("protocol/" + f->name + " is not a usable schema: " +
                                       (error.empty() ? "invalid JSON" : error));
        }
        return v;
    }();
    return instance;
}

bool SchemaValidator::addDocument(json document, std::string& error)
{
    if (!document.is_object()) {
        error = "a schema document must be a JSON object";
        return false;
    }
    if (!compilePatterns(document, error)) return false;
    Document d;
    d.id = document.value("$id", std::string());
    d.root = std::move(document);
    mDocuments.push_back(std::move(d));
    return true;
}

bool SchemaValidator::compilePatterns(const json& schema, std::string& error)
{
    if (schema.is_object()) {
        auto p = schema.find("pattern");
        if (p != schema.end() && p->is_string() && !mPatterns.count(p->get<std::string>())) {
            try {
                mPatterns.emplace(p->get<std::string>(), std::regex(p->get<std::string>(), std::regex::ECMAScript));
            } catch (const std::regex_error& e) {
                error = "invalid pattern " + p->dump() + ": " + e.what();
                return false;
            }
        }
    }
    if (schema.is_structured())
        for (const json& child : schema)
            if (!compilePatterns(child, error)) return false;
    return true;
}

// ---------------------------------------------------------------- look-ups

bool SchemaValidator::resolve(const Document& from, const std::string& ref, Where& out) const
{
    const std::size_t hash = ref.find('#');
    const std::string base = ref.substr(0, hash);
    const std::string fragment = hash == std::string::npos ? std::string() : ref.substr(hash + 1);
    const Document* doc = &from;
    if (!base.empty()) {
        doc = nullptr;
        for (const Document& d : mDocuments)
            if (d.id == base) doc = &d;
        if (!doc) return false;
    }
    if (fragment.empty()) {
        out = {doc, &doc->root};
        return true;
    }
    if (fragment[0] != '/') return false;
    try {
        const json::json_pointer pointer(fragment);
        if (!doc->root.contains(pointer)) return false;
        out = {doc, &doc->root.at(pointer)};
        return true;
    } catch (const json::exception&) {
        return false;
    }
}

bool SchemaValidator::findDefinition(const std::string& nameOrRef, Where& out) const
{
    if (mDocuments.empty()) return false;
    if (nameOrRef.find('#') != std::string::npos) return resolve(mDocuments.front(), nameOrRef, out);
    for (const Document& d : mDocuments) {
        auto defs = d.root.find("$defs");
        if (defs == d.root.end() || !defs->is_object()) continue;
        auto def = defs->find(nameOrRef);
        if (def != defs->end()) {
            out = {&d, &*def};
            return true;
        }
    }
    return false;
}

const json* SchemaValidator::annotation(const char* key) const
{
    for (const Document& d : mDocuments) {
        auto it = d.root.find(key);
        if (it != d.root.end() && it->is_object()) return &*it;
    }
    return nullptr;
}

bool SchemaValidator::hasDefinition(const std::string& definition) const
{
    Where w{};
    return findDefinition(definition, w);
}

std::vector<std::string> SchemaValidator::requestTypes() const
{
    std::vector<std::string> out;
    if (const json* requests = annotation("x-requests"))
        for (auto it = requests->begin(); it != requests->end(); ++it) out.push_back(it.key());
    return out;
}

std::string SchemaValidator::replyDefinition(const std::string& requestType) const
{
    const json* replies = annotation("x-replies");
    if (!replies) return {};
    auto it = replies->find(requestType);
    if (it == replies->end() || !it->is_string()) return {};
    const std::string ref = it->get<std::string>();
    const std::string prefix = "#/$defs/";
    return ref.rfind(prefix, 0) == 0 ? ref.substr(prefix.size()) : ref;
}

// ---------------------------------------------------------------- entry points

bool SchemaValidator::validateMessage(const json& msg, std::string& code, std::string& error) const
{
    code = "schema_violation";
    if (!msg.is_object()) {
        error = "message: expected object, got " + typeOf(msg);
        return false;
    }
    auto type = msg.find("type");
    if (type == msg.end()) {
        error = "message: missing required property \"type\"";
        return false;
    }
    if (!type->is_string()) {
        error = "message.type: expected string, got " + typeOf(*type);
        return false;
    }
    const json* requests = annotation("x-requests");
    auto entry = requests ? requests->find(type->get<std::string>()) : json::const_iterator();
    if (!requests || entry == requests->end() || !entry->is_string()) {
        code = "unknown_message_type";
        error = "unknown message type " + shortDump(*type);
        return false;
    }
    Where w{};
    if (!findDefinition(entry->get<std::string>(), w)) {
        code = "internal";
        error = "no schema for message type " + type->dump();
        return false;
    }
    return check(w, msg, "message", error, 0);
}

bool SchemaValidator::validateServerMessage(const json& msg, const std::string& replyTo,
                                            std::string& error) const
{
    if (!msg.is_object() || !msg.contains("type") || !msg["type"].is_string()) {
        error = "message: expected an object with a string \"type\"";
        return false;
    }
    const std::string type = msg["type"].get<std::string>();
    const json* messages = annotation("x-server-messages");
    auto entry = messages ? messages->find(type) : json::const_iterator();
    Where w{};
    if (!messages || entry == messages->end() || !entry->is_string() ||
        !findDefinition(entry->get<std::string>(), w)) {
        error = "unknown server message type \"" + type + "\"";
        return false;
    }
    if (!check(w, msg, "message", error, 0)) return false;
    if (type != "reply" || replyTo.empty()) return true;
    const std::string dataDefinition = replyDefinition(replyTo);
    if (dataDefinition.empty()) {
        error = "no reply definition for \"" + replyTo + "\"";
        return false;
    }
    return validateAs(dataDefinition, msg["data"], "message.data", error);
}

bool SchemaValidator::validate(const std::string& definition, const json& value,
                               std::string& error) const
{
    return validateAs(definition, value, "body", error);
}

bool SchemaValidator::validateAs(const std::string& definition, const json& value,
                                 const std::string& rootName, std::string& error) const
{
    Where w{};
    if (!findDefinition(definition, w)) {
        error = "no schema definition \"" + definition + "\"";
        return false;
    }
    return check(w, value, rootName, error, 0);
}

// ---------------------------------------------------------------- rules

bool SchemaValidator::check(const Where& where, const json& value, const std::string& path,
                            std::string& error, int depth) const
{
    if (depth > kMaxDepth) {
        error = path + ": schema nesting too deep (a $ref cycle?)";
        return false;
    }
    const json& s = *where.schema;
    if (s.is_boolean()) {
        if (!s.get<bool>()) error = path + ": no value allowed here";
        return s.get<bool>();
    }
    if (!s.is_object()) return true;

    if (auto ref = s.find("$ref"); ref != s.end() && ref->is_string()) {
        Where target{};
        if (!resolve(*where.document, ref->get<std::string>(), target)) {
            error = path + ": schema reference " + ref->dump() + " does not resolve";
            return false;
        }
        if (!check(target, value, path, error, depth + 1)) return false;
    }
    if (auto type = s.find("type"); type != s.end() && !checkType(*type, value, path, error))
        return false;
    if (auto c = s.find("const"); c != s.end() && value != *c) {
        error = path + ": expected " + shortDump(*c) + ", got " + shortDump(value);
        return false;
    }
    if (auto e = s.find("enum"); e != s.end() && e->is_array()) {
        if (std::find(e->begin(), e->end(), value) == e->end()) {
            std::string list;
            for (const json& option : *e) list += (list.empty() ? "" : ", ") + option.dump();
            error = path + ": expected one of " + list + ", got " + shortDump(value);
            return false;
        }
    }
    if (value.is_object() && !checkObject(where, value, path, error, depth)) return false;
    if (value.is_array() && !checkArray(where, value, path, error, depth)) return false;
    if (value.is_number() && !checkNumber(s, value, path, error)) return false;
    if (value.is_string() && !checkString(s, value, path, error)) return false;
    return checkAlternatives(where, value, path, error, depth);
}

bool SchemaValidator::checkType(const json& type, const json& value, const std::string& path,
                                std::string& error) const
{
    std::vector<std::string> names;
    if (type.is_string()) names.push_back(type.get<std::string>());
    else if (type.is_array())
        for (const json& t : type)
            if (t.is_string()) names.push_back(t.get<std::string>());
    for (const std::string& name : names)
        if (hasType(name, value)) return true;
    std::string expected;
    for (std::size_t i = 0; i < names.size(); ++i)
        expected += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i];
    error = path + ": expected " + expected + ", got " + typeOf(value);
    return false;
}

bool SchemaValidator::checkObject(const Where& where, const json& value, const std::string& path,
                                  std::string& error, int depth) const
{
    const json& s = *where.schema;
    if (auto required = s.find("required"); required != s.end() && required->is_array()) {
        for (const json& name : *required) {
            if (name.is_string() && !value.contains(name.get<std::string>())) {
                error = path + ": missing required property " + name.dump();
                return false;
            }
        }
    }
    const auto properties = s.find("properties");
    const bool hasProperties = properties != s.end() && properties->is_object();
    if (hasProperties) {
        for (auto p = properties->begin(); p != properties->end(); ++p) {
            auto member = value.find(p.key());
            if (member == value.end()) continue;
            if (!check({where.document, &p.value()}, *member, childPath(path, p.key()), error, depth + 1))
                return false;
        }
    }
    auto additional = s.find("additionalProperties");
    if (additional == s.end()) return true;
    for (auto member = value.begin(); member != value.end(); ++member) {
        if (hasProperties && properties->contains(member.key())) continue;
        const std::string memberPath = childPath(path, member.key());
        if (additional->is_boolean()) {
            if (additional->get<bool>()) continue;
            error = memberPath + ": unknown property";
            return false;
        }
        if (!check({where.document, &*additional}, member.value(), memberPath, error, depth + 1))
            return false;
    }
    return true;
}

bool SchemaValidator::checkArray(const Where& where, const json& value, const std::string& path,
                                 std::string& error, int depth) const
{
    const json& s = *where.schema;
    if (auto min = s.find("minItems"); min != s.end() && min->is_number() &&
                                       static_cast<double>(value.size()) < min->get<double>()) {
        error = path + ": expected at least " + min->dump() + " items, got " + std::to_string(value.size());
        return false;
    }
    if (auto max = s.find("maxItems"); max != s.end() && max->is_number() &&
                                       static_cast<double>(value.size()) > max->get<double>()) {
        error = path + ": expected at most " + max->dump() + " items, got " + std::to_string(value.size());
        return false;
    }
    auto items = s.find("items");
    if (items == s.end()) return true;
    for (std::size_t i = 0; i < value.size(); ++i)
        if (!check({where.document, &*items}, value[i], indexPath(path, i), error, depth + 1))
            return false;
    return true;
}

bool SchemaValidator::checkNumber(const json& s, const json& value, const std::string& path,
                                  std::string& error) const
{
    const double v = value.get<double>();
    if (auto min = s.find("minimum"); min != s.end() && min->is_number() && v < min->get<double>()) {
        error = path + ": must be >= " + min->dump() + ", got " + value.dump();
        return false;
    }
    if (auto max = s.find("maximum"); max != s.end() && max->is_number() && v > max->get<double>()) {
        error = path + ": must be <= " + max->dump() + ", got " + value.dump();
        return false;
    }
    if (auto min = s.find("exclusiveMinimum");
        min != s.end() && min->is_number() && !(v > min->get<double>())) {
        error = path + ": must be > " + min->dump() + ", got " + value.dump();
        return false;
    }
    return true;
}

bool SchemaValidator::checkString(const json& s, const json& value, const std::string& path,
                                  std::string& error) const
{
    const std::string& text = value.get_ref<const std::string&>();
    const std::size_t length = codePoints(text);
    if (auto min = s.find("minLength"); min != s.end() && min->is_number() &&
                                        static_cast<double>(length) < min->get<double>()) {
        error = path + ": must be at least " + min->dump() + " characters long";
        return false;
    }
    if (auto max = s.find("maxLength"); max != s.end() && max->is_number() &&
                                        static_cast<double>(length) > max->get<double>()) {
        error = path + ": must be at most " + max->dump() + " characters long";
        return false;
    }
    if (auto pattern = s.find("pattern"); pattern != s.end() && pattern->is_string()) {
        auto compiled = mPatterns.find(pattern->get<std::string>());
        if (compiled != mPatterns.end() && !std::regex_search(text, compiled->second)) {
            error = path + ": does not match the pattern " + pattern->dump();
            return false;
        }
    }
    return true;
}

bool SchemaValidator::checkAlternatives(const Where& where, const json& value, const std::string& path,
                                        std::string& error, int depth) const
{
    const json& s = *where.schema;
    for (const char* keyword : {"anyOf", "oneOf"}) {
        auto alternatives = s.find(keyword);
        if (alternatives == s.end() || !alternatives->is_array()) continue;
        const bool exactlyOne = std::string(keyword) == "oneOf";
        int matches = 0;
        std::string reasons;
        for (const json& alternative : *alternatives) {
            std::string reason;
            if (check({where.document, &alternative}, value, path, reason, depth + 1)) ++matches;
            else reasons += (reasons.empty() ? "" : "; or ") + reason;
        }
        if (matches == 0) {
            error = path + ": matches none of the allowed forms (" + reasons + ")";
            return false;
        }
        if (exactlyOne && matches > 1) {
            error = path + ": matches " + std::to_string(matches) + " of the forms where exactly one is allowed";
            return false;
        }
    }
    return true;
}

// ---------------------------------------------------------------- self-check

std::vector<std::string> SchemaValidator::unknownKeywords() const
{
    std::vector<std::string> problems;
    for (const Document& d : mDocuments) walkForUnknown(d, d.root, "", problems);
    return problems;
}

void SchemaValidator::walkForUnknown(const Document& doc, const json& schema, const std::string& pointer,
                                     std::vector<std::string>& problems) const
{
    const std::string where = (doc.id.empty() ? "<no $id>" : doc.id) + "#" + pointer;
    if (schema.is_boolean()) return;
    if (!schema.is_object()) {
        problems.push_back(where + ": a schema must be an object or a boolean");
        return;
    }
    for (auto it = schema.begin(); it != schema.end(); ++it) {
        const std::string& key = it.key();
        const json& v = it.value();
        const std::string at = pointer + "/" + pointerToken(key);
        if (key.rfind("x-", 0) == 0) continue;
        if (!knownKeywords().count(key)) {
            problems.push_back(where + ": keyword \"" + key + "\" is outside the supported subset");
            continue;
        }
        if (key == "$defs" || key == "properties") {
            if (!v.is_object()) problems.push_back(where + ": \"" + key + "\" must be an object");
            else
                for (auto sub = v.begin(); sub != v.end(); ++sub)
                    walkForUnknown(doc, sub.value(), at + "/" + pointerToken(sub.key()), problems);
        } else if (key == "additionalProperties" || key == "items") {
            walkForUnknown(doc, v, at, problems);
        } else if (key == "oneOf" || key == "anyOf") {
            if (!v.is_array()) problems.push_back(where + ": \"" + key + "\" must be an array");
            else
                for (std::size_t i = 0; i < v.size(); ++i)
                    walkForUnknown(doc, v[i], at + "/" + std::to_string(i), problems);
        } else if (key == "$ref") {
            Where target{};
            if (!v.is_string() || !resolve(doc, v.get<std::string>(), target))
                problems.push_back(where + ": $ref " + v.dump() + " does not resolve");
        } else if (key == "type") {
            const json names = v.is_array() ? v : json::array({v});
            for (const json& n : names)
                if (!n.is_string() || !typeNames().count(n.get<std::string>()))
                    problems.push_back(where + ": unknown type " + n.dump());
        } else if (key == "required") {
            if (!v.is_array() || !std::all_of(v.begin(), v.end(), [](const json& n) { return n.is_string(); }))
                problems.push_back(where + ": \"required\" must be an array of names");
        } else if (key == "enum" && !v.is_array()) {
            problems.push_back(where + ": \"enum\" must be an array");
        }
    }
}

} // namespace tlmhub::server
