#pragma once
// The SAH builder's events: each triangle's clipped bound on one axis, as one sortable 64-bit key,
// and their sort. Internal to the builder (sah_kd_builder.cpp).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "formats/stable_radix_sort.h"
#include "formats/triangle_clip.h"

namespace kdpm::sah_detail {

// An event is a triangle's clipped bound on one axis: where it ends, lies (planar) or starts.
// Ordered by position, then end < planar < start (the order the sweep needs), then triangle.
enum EventType : std::uint32_t { kEnd = 0, kPlanar = 1, kStart = 2 };
constexpr std::uint32_t kLocalMask = (1u << 30) - 1;

// Positions as order-preserving integers, so that an event sorts with one 64-bit compare.
// -0 is folded into +0 first, so equal positions have equal bits.
inline std::uint32_t order_bits(float f) {
    f += 0.0f;
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}
inline float from_order_bits(std::uint32_t o) {
    const std::uint32_t u = (o & 0x80000000u) ? (o & 0x7fffffffu) : ~o;
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

struct Event {
    std::uint64_t bits;  // order_bits(pos) << 32 | type << 30 | index of the triangle in the node's list
    // Left uninitialised, also by std::vector's resize: every array of events is written in full
    // before it is read (merges, radix passes), and zeroing each child's lists first would take a
    // large share of split_node's time.
    Event() {}
    explicit Event(std::uint64_t b) : bits(b) {}
    static Event make(float pos, EventType type, std::uint32_t local) {
        return Event{static_cast<std::uint64_t>(order_bits(pos)) << 32 | static_cast<std::uint64_t>(type) << 30 | local};
    }
    std::uint32_t pos_bits() const { return static_cast<std::uint32_t>(bits >> 32); }
    float pos() const { return from_order_bits(pos_bits()); }
    EventType type() const { return static_cast<EventType>((bits >> 30) & 3u); }
    std::uint32_t local() const { return static_cast<std::uint32_t>(bits) & kLocalMask; }
    Event with_local(std::uint32_t local) const { return Event{(bits & ~std::uint64_t{kLocalMask}) | local}; }
};

inline bool operator<(const Event& a, const Event& b) { return a.bits < b.bits; }

// Sorts one axis' events, which arrive in triangle (local) order: a stable sort by position and
// type then orders them as operator< does. Radix passes pay off from about a thousand events;
// the few events of a small node, up to 64, sort fastest by insertion.
// Events are distinct (each names its triangle), so every sort gives the same order.
inline void sort_events(std::vector<Event>& ev) {
    if (ev.size() <= 64) {
        Event* e = ev.data();
        for (std::size_t i = 1; i < ev.size(); ++i) {
            const Event x = e[i];
            std::size_t j = i;
            for (; j > 0 && x < e[j - 1]; --j) e[j] = e[j - 1];
            e[j] = x;
        }
        return;
    }
    if (ev.size() < 1024) {
        std::sort(ev.begin(), ev.end());
        return;
    }
    static_assert(32 + 2 <= kRadixKeyBits, "position and type must fit the radix key");
    stable_radix_sort(ev, [](const Event& e) { return e.bits >> 30; });
}

inline void add_events(const AxisBox& b, std::uint32_t local, std::vector<Event> (&ev)[3]) {
    for (int a = 0; a < 3; ++a) {
        if (b.lo[a] == b.hi[a]) {
            ev[a].push_back(Event::make(b.lo[a], kPlanar, local));
        } else {
            ev[a].push_back(Event::make(b.lo[a], kStart, local));
            ev[a].push_back(Event::make(b.hi[a], kEnd, local));
        }
    }
}

}  // namespace kdpm::sah_detail
