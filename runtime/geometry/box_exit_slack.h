#pragma once
// The exit distance every box test compares with (wide nodes, instance BVH nodes, packets of
// rays at instance nodes) is raised by 2^-20 of itself, as Embree's conservative slab test does:
// the few roundings of (box - origin) / direction then cannot turn a grazing ray away from a box
// it enters, however far from the scene the ray starts, where the boxes' margin covers only rays
// from within the scene's reach.
namespace kdpm {

inline constexpr float kExitSlack = 1.0f + 1.0f / 1048576.0f;

}  // namespace kdpm
