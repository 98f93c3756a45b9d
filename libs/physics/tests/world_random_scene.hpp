// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <algorithm>
#include <vector>

// A random world for the brute-force comparisons, with the test's own record of what it put
// in, so expected answers come from the geometry functions rather than from the World.
namespace e2d::physics::test {

struct ShapeRecord {
    ShapeId id;
    BodyId body;
    ShapeGeometry geometry;
    Filter filter;
    bool isSensor = false;
};

struct BodyRecord {
    BodyId id;
    BodyType type = BodyType::Static;
    Vec2 position{0.0f, 0.0f};
    float angle = 0.0f;
    bool enabled = true;
};

class RandomScene {
public:
    RandomScene(std::uint32_t seed, int bodyCount, float extent) : random_(seed), extent_(extent) {
        for (int i = 0; i < bodyCount; ++i) {
            addBody();
        }
        index();
    }

    World world;
    std::vector<BodyRecord> bodies;
    std::vector<ShapeRecord> shapes;

    Random& random() { return random_; }

    void addBody() {
        BodyRecord record;
        record.type = static_cast<BodyType>(random_.below(3));
        record.position = {random_.uniform(-extent_, extent_), random_.uniform(-extent_, extent_)};
        record.angle = random_.uniform(-3.0f, 3.0f);
        BodyDef def;
        def.type = record.type;
        def.position = record.position;
        def.angle = record.angle;
        record.id = world.createBody(def);
        bodies.push_back(record);
        int count = 1 + random_.below(3);
        for (int i = 0; i < count; ++i) {
            addShape(record.id);
        }
    }

    void addShape(BodyId body) {
        ShapeRecord record;
        record.body = body;
        record.geometry = randomGeometry();
        // A few categories so that masks and groups reject some pairs.
        static constexpr std::uint64_t kCategories[] = {0x1, 0x2, 0x4};
        record.filter.categoryBits = kCategories[random_.below(3)];
        record.filter.maskBits = random_.below(4) == 0 ? ~std::uint64_t{0x2} : ~std::uint64_t{0};
        record.filter.group = random_.below(5) == 0 ? (random_.below(2) == 0 ? 1 : -1) : 0;
        record.isSensor = random_.below(8) == 0;
        ShapeDef def;
        def.filter = record.filter;
        def.isSensor = record.isSensor;
        record.id = world.createShape(body, def, record.geometry);
        shapes.push_back(record);
    }

    ShapeGeometry randomGeometry() {
        Vec2 offset{random_.uniform(-0.5f, 0.5f), random_.uniform(-0.5f, 0.5f)};
        switch (random_.below(4)) {
        case 0:
            return Circle{offset, random_.uniform(0.1f, 1.0f)};
        case 1:
            return Capsule{offset, offset + Vec2(random_.uniform(-1.0f, 1.0f), 1.0f),
                           random_.uniform(0.1f, 0.5f)};
        case 2:
            return Segment{
                offset, offset + Vec2(random_.uniform(0.2f, 2.0f), random_.uniform(-1.0f, 1.0f))};
        default:
            return makeOffsetBox(random_.uniform(0.1f, 1.0f), random_.uniform(0.1f, 1.0f), offset,
                                 random_.uniform(-3.0f, 3.0f));
        }
    }

    /// Builds the body lookup bodyOf() and transformOf() use; call after adding or removing
    /// bodies, before those two.
    void index() {
        table_.assign(bodies.size() + shapes.size() + 64, nullptr);
        for (const BodyRecord& b : bodies) {
            if (b.id.index1 >= table_.size()) {
                table_.resize(b.id.index1 + 1, nullptr);
            }
            table_[b.id.index1] = &b;
        }
    }
    [[nodiscard]] const BodyRecord& bodyOf(const ShapeRecord& shape) const {
        return *table_.at(shape.body.index1);
    }
    [[nodiscard]] Transform transformOf(const ShapeRecord& shape) const {
        const BodyRecord& body = bodyOf(shape);
        return {body.position, Rot::fromAngle(body.angle)};
    }

    void moveBody(BodyRecord& body, Vec2 position, float angle) {
        body.position = position;
        body.angle = angle;
        world.setTransform(body.id, position, angle);
    }

    void destroyBody(std::size_t index) {
        BodyId id = bodies[index].id;
        world.destroyBody(id);
        bodies.erase(bodies.begin() + static_cast<std::ptrdiff_t>(index));
        std::erase_if(shapes, [&](const ShapeRecord& s) { return s.body == id; });
    }

    void destroyShape(std::size_t index) {
        world.destroyShape(shapes[index].id);
        shapes.erase(shapes.begin() + static_cast<std::ptrdiff_t>(index));
    }

    [[nodiscard]] float extent() const { return extent_; }

private:
    std::vector<const BodyRecord*> table_; // by BodyId::index1
    Random random_;
    float extent_;
};

inline bool seenBy(const ShapeRecord& shape, const QueryFilter& filter) {
    return (!shape.isSensor || filter.includeSensors) &&
           (shape.filter.categoryBits & filter.maskBits) != 0 &&
           (shape.filter.maskBits & filter.categoryBits) != 0;
}

inline std::vector<ShapeId> sortedIds(std::vector<ShapeId> ids) {
    std::sort(ids.begin(), ids.end(), [](ShapeId a, ShapeId b) { return a.index1 < b.index1; });
    return ids;
}

} // namespace e2d::physics::test
