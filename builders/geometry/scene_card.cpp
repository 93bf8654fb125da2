#include "builders/geometry/scene_card.h"

#include <rapidjson/document.h>
#include <rapidjson/error/en.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "builders/geometry/import/isolated_import.h"
#include "builders/geometry/import/texture_import.h"
#include "formats/affine_map.h"
#include "formats/camera_check.h"
#include "formats/format_error.h"
#include "formats/scene_limits.h"

namespace kdpm {

namespace {

namespace fs = std::filesystem;
using rapidjson::Value;

struct Card {
    std::string name;
    rapidjson::Document doc;

    [[noreturn]] void fail(const std::string& why) const { throw FormatError(name + ": " + why); }

    void vec3(const Value& v, const char* key, float (&out)[3]) const {
        if (!v.IsArray() || v.Size() != 3) fail(std::string("\"") + key + "\" must be an array of 3 numbers");
        for (unsigned i = 0; i < 3; ++i) {
            if (!v[i].IsNumber()) fail(std::string("\"") + key + "\" must be an array of 3 numbers");
            out[i] = static_cast<float>(v[i].GetDouble());
            if (!std::isfinite(out[i]))
                fail(std::string("\"") + key + "\" has a value that does not fit a float: " +
                     std::to_string(v[i].GetDouble()));
        }
    }
    std::uint32_t count(const Value& v, const char* key, std::uint32_t lo, std::uint32_t hi) const {
        if (!v.IsUint() || v.GetUint() < lo || v.GetUint() > hi)
            fail(std::string("\"") + key + "\" must be an integer in [" + std::to_string(lo) + ", " +
                 std::to_string(hi) + "]");
        return v.GetUint();
    }
    void only_keys(const Value& obj, const char* where, std::set<std::string> allowed) const {
        for (auto it = obj.MemberBegin(); it != obj.MemberEnd(); ++it)
            if (!allowed.count(it->name.GetString()))
                fail(std::string("unknown key \"") + it->name.GetString() + "\" in " + where);
    }
};

Card parse_card(std::string json, const std::string& name);

Card read_card(const fs::path& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw FormatError(path.string() + ": no such scene card");
    // Checked before opening: a FIFO would block the open, a device would never end.
    if (!fs::is_regular_file(status)) throw FormatError(path.string() + ": the scene card is not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FormatError(path.string() + ": cannot open scene card");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_card(text.str(), path.string());
}

Card parse_card(std::string json, const std::string& name) {
    Card card{name, {}};
    if (json.compare(0, 3, "\xEF\xBB\xBF") == 0) json.erase(0, 3);  // a UTF-8 byte order mark, as some editors write
    // Iterative parsing: a hostile card cannot exhaust the stack.
    card.doc.Parse<rapidjson::kParseIterativeFlag>(json.c_str());
    if (card.doc.HasParseError())
        card.fail(std::string("not valid JSON: ") + rapidjson::GetParseError_En(card.doc.GetParseError()) +
                  " at byte " + std::to_string(card.doc.GetErrorOffset()));
    if (!card.doc.IsObject()) card.fail("a scene card must be a JSON object");
    card.only_keys(card.doc, "the card",
                   {"mesh", "shared_scene", "instances", "up", "camera", "lights", "photons", "bounces", "k", "comment"});
    return card;
}

// A camera framed from the bounds fails only for a scene too large for float arithmetic.
void check_framed_camera(const Scene& scene, const std::string& name) {
    try {
        check_camera(scene.camera, name + " (framed from the scene bounds)");
    } catch (const std::runtime_error& e) {
        throw FormatError(e.what());
    }
}

// Everything a card sets beyond its mesh: up axis, defaults, lights, camera.
void apply_card(const Card& card, Scene& scene) {
    const Value& doc = card.doc;
    std::uint32_t up = 1;
    if (doc.HasMember("up")) {
        const Value& u = doc["up"];
        const std::string s = u.IsString() ? u.GetString() : "";
        if (s == "x" || s == "+x") up = 0;
        else if (s == "y" || s == "+y") up = 1;
        else if (s == "z" || s == "+z") up = 2;
        else card.fail("\"up\" must be \"x\", \"y\" or \"z\"");
    }
    scene.up_axis = up;
    // The limits of the options these defaults stand in for (kdpm-shoot-photons, kdpm-render).
    if (doc.HasMember("photons")) scene.photons = card.count(doc["photons"], "photons", 1, kMaxPhotons);
    if (doc.HasMember("bounces")) scene.bounces = card.count(doc["bounces"], "bounces", 0, kMaxBounces);
    if (doc.HasMember("k")) scene.k = card.count(doc["k"], "k", 1, kMaxEstimateK);
    if (doc.HasMember("lights")) {
        const Value& lights = doc["lights"];
        if (!lights.IsArray()) card.fail("\"lights\" must be an array");
        for (const Value& l : lights.GetArray()) {
            if (!l.IsObject()) card.fail("each light must be an object");
            card.only_keys(l, "a light", {"p0", "e1", "e2", "radiance", "comment"});
            for (const char* key : {"p0", "e1", "e2", "radiance"})
                if (!l.HasMember(key)) card.fail(std::string("a light needs \"") + key + "\"");
            float p0[3], e1[3], e2[3], radiance[3];
            card.vec3(l["p0"], "p0", p0);
            card.vec3(l["e1"], "e1", e1);
            card.vec3(l["e2"], "e2", e2);
            card.vec3(l["radiance"], "radiance", radiance);
            const AreaLightRecord light = make_parallelogram_light(p0, e1, e2, radiance);
            if (!std::isfinite(light.area) || !std::isfinite(light.power))
                card.fail("light " + std::to_string(scene.lights.size()) + ": its area or power overflows a float");
            if (radiance[0] < 0.0f || radiance[1] < 0.0f || radiance[2] < 0.0f)
                card.fail("light " + std::to_string(scene.lights.size()) + ": \"radiance\" must not be negative");
            scene.lights.push_back(light);
        }
    }
    if (doc.HasMember("camera")) {
        const Value& c = doc["camera"];
        if (!c.IsObject()) card.fail("\"camera\" must be an object");
        card.only_keys(c, "the camera", {"eye", "lookat", "up", "vfov", "width", "height", "comment"});
        for (const char* key : {"eye", "lookat", "up", "vfov"})
            if (!c.HasMember(key)) card.fail(std::string("the camera needs \"") + key + "\"");
        CameraRecord& cam = scene.camera;
        card.vec3(c["eye"], "eye", cam.eye);
        card.vec3(c["lookat"], "lookat", cam.lookat);
        card.vec3(c["up"], "up", cam.up);
        if (!c["vfov"].IsNumber() || !(c["vfov"].GetDouble() > 0.0 && c["vfov"].GetDouble() < 180.0))
            card.fail("\"vfov\" must be a number of degrees in (0, 180)");
        cam.vfov_degrees = static_cast<float>(c["vfov"].GetDouble());
        cam.width = c.HasMember("width") ? card.count(c["width"], "width", 1, kMaxImageSide) : 512;
        cam.height = c.HasMember("height") ? card.count(c["height"], "height", 1, kMaxImageSide) : 512;
        try {
            check_camera(cam, card.name);
        } catch (const std::runtime_error& e) {
            throw FormatError(e.what());
        }
        scene.has_camera = true;
    } else {
        frame_camera(scene);
        check_framed_camera(scene, card.name);
    }
}


// One "instances" entry's map: T(translate) * R(rotate) * S(scale), or "matrix" (12 numbers,
// 3x4 row-major) alone.
Affine instance_map(const Card& card, const Value& e, std::size_t index) {
    const std::string which = "instance " + std::to_string(index);
    if (e.HasMember("matrix")) {
        if (e.HasMember("translate") || e.HasMember("rotate") || e.HasMember("scale"))
            card.fail(which + ": \"matrix\" stands alone, without \"translate\", \"rotate\" or \"scale\"");
        const Value& m = e["matrix"];
        if (!m.IsArray() || m.Size() != 12) card.fail(which + ": \"matrix\" must be 12 numbers (3x4, row by row)");
        Affine a{};
        for (unsigned i = 0; i < 12; ++i) {
            if (!m[i].IsNumber()) card.fail(which + ": \"matrix\" must be 12 numbers (3x4, row by row)");
            a.m[i / 4][i % 4] = static_cast<float>(m[i].GetDouble());
        }
        return a;
    }
    float t[3] = {0, 0, 0}, s[3] = {1, 1, 1}, axis[3] = {0, 1, 0};
    double degrees = 0.0;
    if (e.HasMember("translate")) card.vec3(e["translate"], "translate", t);
    if (e.HasMember("scale")) {
        if (e["scale"].IsNumber()) s[0] = s[1] = s[2] = static_cast<float>(e["scale"].GetDouble());
        else card.vec3(e["scale"], "scale", s);
    }
    if (e.HasMember("rotate")) {
        const Value& r = e["rotate"];
        if (!r.IsObject() || !r.HasMember("axis") || !r.HasMember("degrees") || !r["degrees"].IsNumber())
            card.fail(which + ": \"rotate\" must be {\"axis\": [x, y, z], \"degrees\": d}");
        card.only_keys(r, "a rotation", {"axis", "degrees"});
        card.vec3(r["axis"], "axis", axis);
        degrees = r["degrees"].GetDouble();
        if (!std::isfinite(degrees)) card.fail(which + ": \"degrees\" must be finite");
    }
    const double len = std::sqrt(double(axis[0]) * axis[0] + double(axis[1]) * axis[1] + double(axis[2]) * axis[2]);
    if (!(len > 0.0) || !std::isfinite(len)) card.fail(which + ": the rotation axis must not be zero");
    const double x = axis[0] / len, y = axis[1] / len, z = axis[2] / len;
    const double a = degrees * 3.14159265358979323846 / 180.0, c = std::cos(a), sn = std::sin(a), k = 1.0 - c;
    const double r[3][3] = {{c + x * x * k, x * y * k - z * sn, x * z * k + y * sn},
                            {y * x * k + z * sn, c + y * y * k, y * z * k - x * sn},
                            {z * x * k - y * sn, z * y * k + x * sn, c + z * z * k}};
    Affine m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m.m[i][j] = static_cast<float>(r[i][j] * s[j]);
        m.m[i][3] = t[i];
    }
    return m;
}

InstanceCard instance_card(const Card& card, const fs::path& card_path) {
    const Value& list = card.doc["instances"];
    if (card.doc.HasMember("mesh") || card.doc.HasMember("shared_scene"))
        card.fail("a card places \"instances\" or names a \"mesh\", not both (build the mesh as an object and place it)");
    if (!list.IsArray() || list.Empty()) card.fail("\"instances\" must be a non-empty array");
    InstanceCard out;
    for (unsigned i = 0; i < list.Size(); ++i) {
        const Value& e = list[i];
        if (!e.IsObject()) card.fail("each instance must be an object");
        card.only_keys(e, "an instance", {"object", "translate", "rotate", "scale", "matrix", "repeat", "comment"});
        if (!e.HasMember("object") || !e["object"].IsString() || e["object"].GetStringLength() == 0)
            card.fail("instance " + std::to_string(i) + " needs \"object\": the path of a .kdg, relative to the card");
        const fs::path object = card_path.parent_path() / e["object"].GetString();
        std::uint32_t index = 0;
        while (index < out.objects.size() && out.objects[index] != object) ++index;
        if (index == out.objects.size()) out.objects.push_back(object);
        const Affine m = instance_map(card, e, i);
        if (!usable_affine(m)) card.fail("instance " + std::to_string(i) + ": its transform is not finite or not invertible");
        // "repeat": the placement copied on a grid, each copy moved by step * (i, j, k).
        std::uint32_t count[3] = {1, 1, 1};
        float step[3] = {0, 0, 0};
        if (e.HasMember("repeat")) {
            const Value& r = e["repeat"];
            if (!r.IsObject() || !r.HasMember("count") || !r.HasMember("step"))
                card.fail("instance " + std::to_string(i) + ": \"repeat\" must be {\"count\": [nx, ny, nz], \"step\": [x, y, z]}");
            card.only_keys(r, "a repeat", {"count", "step"});
            const Value& c = r["count"];
            if (!c.IsArray() || c.Size() != 3) card.fail("\"count\" must be an array of 3 integers");
            for (unsigned a = 0; a < 3; ++a) count[a] = card.count(c[a], "count", 1, kMaxInstances);
            card.vec3(r["step"], "step", step);
        }
        const std::uint64_t copies = std::uint64_t{count[0]} * count[1] * count[2];
        if (out.instances.size() + copies > kMaxInstances)
            card.fail("the card places more than " + std::to_string(kMaxInstances) + " instances");
        for (std::uint32_t a = 0; a < count[0]; ++a)
            for (std::uint32_t b = 0; b < count[1]; ++b)
                for (std::uint32_t c = 0; c < count[2]; ++c) {
                    InstanceRecord rec{};
                    std::memcpy(rec.world_from_object, m.m, sizeof rec.world_from_object);
                    rec.world_from_object[3] += step[0] * a;
                    rec.world_from_object[7] += step[1] * b;
                    rec.world_from_object[11] += step[2] * c;
                    rec.object = index;
                    out.instances.push_back(rec);
                }
    }
    return out;
}

}  // namespace

bool card_places_instances(const fs::path& card) { return is_scene_card(card) && read_card(card).doc.HasMember("instances"); }

InstanceCard read_instance_card(const fs::path& card_path) {
    const Card card = read_card(card_path);
    InstanceCard out = instance_card(card, card_path);
    out.card_camera = card.doc.HasMember("camera");
    // The camera, when the card has none, is framed later from the placed objects' box.
    apply_card(card, out.settings);
    return out;
}

void apply_scene_card(const std::string& json, const std::string& name, Scene& scene) {
    apply_card(parse_card(json, name), scene);
}

bool is_scene_card(const fs::path& input) {
    std::string ext = input.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".json";
}

fs::path card_mesh_path(const fs::path& card_path) {
    const Card card = read_card(card_path);
    const Value& doc = card.doc;
    if (doc.HasMember("instances")) card.fail("a card of \"instances\" has no mesh of its own");
    if (!doc.HasMember("mesh") || !doc["mesh"].IsString()) card.fail("\"mesh\" (a path relative to the card) is required");
    if (doc.HasMember("shared_scene")) {
        if (!doc["shared_scene"].IsString()) card.fail("\"shared_scene\" must be a string");
        if (const char* env = std::getenv("KDPM_SCENES"); env && *env) {
            fs::path p = fs::path(env) / doc["shared_scene"].GetString();
            std::error_code ec;
            if (fs::is_regular_file(p, ec)) return p;
        }
    }
    return card_path.parent_path() / doc["mesh"].GetString();
}

Scene load_scene_input(const fs::path& input) {
    if (!is_scene_card(input)) {
        Scene scene = import_mesh_isolated(input);
        load_textures(scene);
        check_scene_extent(scene);
        frame_camera(scene);
        check_framed_camera(scene, input.string());
        return scene;
    }
    const fs::path mesh = card_mesh_path(input);
    const Card card = read_card(input);
    Scene scene = import_mesh_isolated(mesh);
    load_textures(scene);
    check_scene_extent(scene);
    apply_card(card, scene);
    return scene;
}

}  // namespace kdpm
