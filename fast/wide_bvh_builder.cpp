#include "fast/wide_bvh_builder.h"

#include "fast/simd.h"
#include "fast/task_pool.h"
#include "fast/triangle_packet.h"
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <utility>

namespace rtlab {
namespace {

using Float4 = Simd<float, 4>;
using Int4 = Simd<int32_t, 4>;

// Subtrees of at least this many primitives are handed to the task pool, and nodes of at least
// kParallelBinning have their primitives binned in chunks on every thread. Below, a task costs
// more than it shares.
constexpr uint32_t kParallelSubtree = 4096;
constexpr uint32_t kParallelBinning = 65536;

// A box in lanes x, y, z (lane 3 is not looked at). extend() is Bounds3f::extend's comparison
// in the same operand order, so boxes come out bit for bit as the framework's unions (a NaN
// coordinate never enters), and a node's box is exactly the union of its primitives'.
// No default initialiser: a node's bins are cleared only as far as it uses them.
struct Box {
    Float4 lower, upper;

    static Box empty() { return {broadcast<4>(kInfinity), broadcast<4>(-kInfinity)}; }

    void extend(Float4 l, Float4 u) {
        lower = l < lower ? l : lower;
        upper = upper < u ? u : upper;
    }
    void extend(const Box& b) { extend(b.lower, b.upper); }
    // Half the surface area: the SAH compares ratios of areas, so the factor 2 cancels.
    float halfArea() const {
        Float4 d = upper - lower;
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }
    Bounds3f bounds3f() const { return Bounds3f{Vec3(lower[0], lower[1], lower[2]), Vec3(upper[0], upper[1], upper[2])}; }
};

// A primitive's box with its id in the lower corner's unused lane: 32 bytes, two SIMD loads.
struct PrimRef {
    Float4 lower, upper;

    uint32_t id() const { return std::bit_cast<uint32_t>(lower[3]); }
    // Twice the box's centre (binning only compares, so the halving is left out), lane 3 zero:
    // the id's bits would be a denormal number, slow in arithmetic on some processors.
    Float4 centre2() const { return __builtin_shuffle(lower, Float4{}, Int4{0, 1, 2, 4}) + upper; }
};

using PrimRefs = HugePageVector<PrimRef>;

// Primitives [begin, end) of the reference array with their boxes and the box of their centres
// (twice the centres, as PrimRef::centre2), at binary depth `depth` below the root.
struct Range {
    uint32_t begin = 0, end = 0;
    Box bounds = Box::empty(), centres = Box::empty();
    int depth = 0;

    uint32_t size() const { return end - begin; }
    void add(const PrimRef& ref) {
        bounds.extend(ref.lower, ref.upper);
        Float4 c = ref.centre2();
        centres.extend(c, c);
    }
};

// Maps a centre to its bin on each axis: bins equally wide over the range's centres. An axis
// whose centres do not spread (or spread over an infinite or NaN extent) gets scale 0: every
// primitive lands in bin 0 there, and no split is looked for.
struct BinMapping {
    int bins;
    Float4 offset, scale;
    float lastBin;

    BinMapping(const Box& centres, int binCount) : bins(binCount), offset(centres.lower), lastBin(float(bins - 1)) {
        Float4 extent = centres.upper - centres.lower;
        Float4 s = float(bins) / extent;
        // Written so that NaN fails: a finite positive scale passes, anything else becomes 0.
        scale = (extent > Float4{}) & (s < broadcast<4>(kInfinity)) ? s : Float4{};
    }
    bool splittable(int axis) const { return scale[axis] > 0.0f; }
    Int4 operator()(Float4 centre2) const {
        Float4 f = (centre2 - offset) * scale;
        f = f > Float4{} ? f : Float4{};  // also NaN
        f = f < broadcast<4>(lastBin) ? f : broadcast<4>(lastBin);
        return __builtin_convertvector(f, Int4);
    }
};

struct Bins {
    Box box[3][kMaxSahBins];
    uint32_t count[3][kMaxSahBins];

    explicit Bins(int bins) {
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < bins; ++i) {
                box[axis][i] = Box::empty();
                count[axis][i] = 0;
            }
    }
    void add(const PrimRef* first, const PrimRef* last, const BinMapping& map) {
        for (const PrimRef* ref = first; ref != last; ++ref) {
            Int4 bin = map(ref->centre2());
            for (int axis = 0; axis < 3; ++axis) {
                box[axis][bin[axis]].extend(ref->lower, ref->upper);
                ++count[axis][bin[axis]];
            }
        }
    }
    void merge(const Bins& other, int bins) {
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < bins; ++i) {
                box[axis][i].extend(other.box[axis][i]);
                count[axis][i] += other.count[axis][i];
            }
    }
};

// A split between bins: left are the primitives whose bin on `axis` is below `bin`. cost is the
// SAH sum of both sides' areas times their packets; axis < 0 when no plane separates anything.
struct Split {
    float cost = kInfinity;
    int axis = -1;
    int bin = 0;
};

// A range with the builder's verdict on it.
struct Child {
    Range range;
    bool leaf = false;
    Split split;  // for an interior child; axis < 0: halve the range in its present order
};

template <int W>
class Builder {
public:
    Builder(PrimRefs& refs, const WideBvhBuildOptions& options, TaskPool& pool, HugePageVector<WideBvhNode<W>>& nodes)
        : refs_(refs), options_(options), pool_(pool), nodes_(nodes) {}

    // The verdict on a range: a leaf, or the split the SAH prefers.
    Child decide(const Range& range) {
        Child child{range, true, {}};
        uint32_t n = range.size();
        if (n <= 1 || range.depth >= kMaxBvhDepth - 1) return child;
        BinMapping map = mapping(range);
        if (map.splittable(0) || map.splittable(1) || map.splittable(2)) child.split = bestSplit(range, map);
        float area = range.bounds.halfArea();
        float leafCost = options_.packetCost * float(packets(n)) * area;
        float splitCost = options_.traversalCost * area + options_.packetCost * child.split.cost;
        bool separable = child.split.axis >= 0;
        child.leaf = n <= uint32_t(options_.maxLeaf) && (!separable || leafCost <= splitCost);
        return child;
    }

    // Fills node `index` with up to W children, then builds the interior ones below it.
    void build(const Child& root, uint32_t index) {
        Child children[W];
        int count = 1;
        children[0] = root;
        while (count < W) {
            // The interior child with the largest area: the likeliest to be entered.
            int open = -1;
            float largest = -1.0f;
            for (int i = 0; i < count; ++i)
                if (!children[i].leaf && children[i].range.bounds.halfArea() > largest) {
                    open = i;
                    largest = children[i].range.bounds.halfArea();
                }
            if (open < 0) break;
            auto [left, right] = divide(children[open]);
            children[open] = decide(left);
            children[count++] = decide(right);
        }

        int interior = 0;
        for (int i = 0; i < count; ++i) interior += !children[i].leaf;
        uint32_t first = interior > 0 ? nodeCount_.fetch_add(uint32_t(interior), std::memory_order_relaxed) : 0;
        WideBvhNode<W>& node = nodes_[index];
        uint32_t next = first;
        for (int slot = 0; slot < W; ++slot) {
            if (slot >= count) {
                node.setEmpty(slot);
                continue;
            }
            const Range& r = children[slot].range;
            if (children[slot].leaf)
                node.setChild(slot, r.bounds.bounds3f(), kLeafFlag | r.begin, r.size());
            else
                node.setChild(slot, r.bounds.bounds3f(), next++, 0);
        }
        next = first;
        for (int slot = 0; slot < count; ++slot) {
            if (children[slot].leaf) continue;
            uint32_t childIndex = next++;
            if (children[slot].range.size() >= kParallelSubtree && pool_.threads() > 1)
                pool_.run([this, child = children[slot], childIndex] { build(child, childIndex); }, pending_);
            else
                build(children[slot], childIndex);
        }
    }

    // Builds the whole tree below the root's node 0 and waits for every task.
    void buildRoot(const Child& root) {
        nodeCount_ = 1;
        if (root.leaf) {
            nodes_[0].setChild(0, root.range.bounds.bounds3f(), kLeafFlag | root.range.begin, root.range.size());
            for (int slot = 1; slot < W; ++slot) nodes_[0].setEmpty(slot);
        } else {
            build(root, 0);
        }
        pool_.waitFor(pending_);
    }

    uint32_t nodeCount() const { return nodeCount_.load(); }

private:
    uint32_t packets(uint32_t n) const { return (n + TrianglePacket::kLanes - 1) / TrianglePacket::kLanes; }

    // A small node gets fewer bins: sweeping 32 bins per axis costs far more than binning a
    // handful of primitives, and a few bins separate a few primitives about as well.
    BinMapping mapping(const Range& range) const {
        return BinMapping(range.centres, int(std::min<uint32_t>(uint32_t(options_.bins), std::max(4u, range.size()))));
    }

    Split bestSplit(const Range& range, const BinMapping& map) {
        int bins = map.bins;
        Bins total(bins);
        const PrimRef* first = refs_.data() + range.begin;
        uint32_t n = range.size();
        int chunks = n >= kParallelBinning ? pool_.threads() : 1;
        if (chunks == 1) {
            total.add(first, first + n, map);
        } else {
            // One chunk per thread, each into bins of its own; merging is exact (min, max, sums),
            // so the tree does not depend on the thread count.
            std::vector<Bins> partial(chunks, Bins(bins));
            std::atomic<int> pending{0};
            for (int c = 1; c < chunks; ++c)
                pool_.run([&, c] { partial[c].add(first + size_t(n) * c / chunks, first + size_t(n) * (c + 1) / chunks, map); },
                          pending);
            partial[0].add(first, first + n / chunks, map);
            pool_.waitFor(pending);
            for (const Bins& p : partial) total.merge(p, bins);
        }

        // Sweep each axis from the right (areas and counts of every right side), then from the
        // left, pricing each side by the packets its primitives fill. Ties go to the lower axis,
        // then the lower bin.
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (!map.splittable(axis)) continue;
            float rightArea[kMaxSahBins];
            uint32_t rightCount[kMaxSahBins];
            Box side = Box::empty();
            uint32_t count = 0;
            for (int i = bins - 1; i > 0; --i) {
                side.extend(total.box[axis][i]);
                count += total.count[axis][i];
                rightArea[i] = side.halfArea();
                rightCount[i] = count;
            }
            side = Box::empty();
            count = 0;
            for (int i = 1; i < bins; ++i) {
                side.extend(total.box[axis][i - 1]);
                count += total.count[axis][i - 1];
                if (count == 0 || rightCount[i] == 0) continue;
                float cost = side.halfArea() * float(packets(count)) + rightArea[i] * float(packets(rightCount[i]));
                if (cost < best.cost) best = {cost, axis, i};
            }
        }
        return best;
    }

    // The two halves of an interior child: the SAH's plane, or halves of its present order when
    // no plane separates (centres that coincide, or a leaf that must be split).
    std::pair<Range, Range> divide(const Child& child) {
        const Range& r = child.range;
        Range left, right;
        left.depth = right.depth = r.depth + 1;
        left.begin = r.begin;
        right.end = r.end;
        if (child.split.axis < 0) {
            left.end = right.begin = r.begin + r.size() / 2;
            for (uint32_t i = left.begin; i < left.end; ++i) left.add(refs_[i]);
            for (uint32_t i = right.begin; i < right.end; ++i) right.add(refs_[i]);
            return {left, right};
        }
        BinMapping map = mapping(r);
        int axis = child.split.axis, bin = child.split.bin;
        auto isLeft = [&](const PrimRef& ref) { return map(ref.centre2())[axis] < bin; };
        uint32_t i = r.begin, j = r.end;
        for (;;) {
            while (i < j && isLeft(refs_[i])) left.add(refs_[i++]);
            while (i < j && !isLeft(refs_[j - 1])) right.add(refs_[--j]);
            if (i == j) break;
            std::swap(refs_[i], refs_[j - 1]);
        }
        left.end = right.begin = i;
        return {left, right};
    }

    PrimRefs& refs_;
    const WideBvhBuildOptions& options_;
    TaskPool& pool_;
    HugePageVector<WideBvhNode<W>>& nodes_;
    std::atomic<uint32_t> nodeCount_{0};
    std::atomic<int> pending_{0};
};

}  // namespace

template <int W>
WideBvh<W> buildWideBvh(std::span<const Bounds3f> primBounds, const WideBvhBuildOptions& options) {
    if (options.bins < 2 || options.bins > kMaxSahBins || options.maxLeaf < 1)
        throw Error("wide BVH builder: bins must be in 2.." + std::to_string(kMaxSahBins) + " and maxLeaf at least 1");
    WideBvh<W> wide;
    auto n = static_cast<uint32_t>(primBounds.size());
    if (n == 0) return wide;
    TaskPool pool(n >= kParallelSubtree ? (options.threads > 0 ? options.threads : availableCpus()) : 1);

    // The references and the root's boxes, in one chunk per thread.
    PrimRefs refs(n);
    int chunks = pool.threads();
    std::vector<Range> parts(chunks);
    std::atomic<int> pending{0};
    auto fill = [&](int c) {
        Range& part = parts[c];
        for (uint32_t i = uint32_t(size_t(n) * c / chunks); i < uint32_t(size_t(n) * (c + 1) / chunks); ++i) {
            const Bounds3f& b = primBounds[i];
            refs[i] = PrimRef{Float4{b.lower.x, b.lower.y, b.lower.z, std::bit_cast<float>(i)},
                              Float4{b.upper.x, b.upper.y, b.upper.z, 0.0f}};
            part.add(refs[i]);
        }
    };
    for (int c = 1; c < chunks; ++c) pool.run([&, c] { fill(c); }, pending);
    fill(0);
    pool.waitFor(pending);
    Range root;
    root.end = n;
    for (const Range& part : parts) {
        root.bounds.extend(part.bounds);
        root.centres.extend(part.centres);
    }

    // A tree whose nodes all have two children or more has fewer nodes than primitives. The
    // pages of the capacity that the tree does not use are never touched, so they cost address
    // space, not memory, and the nodes need no copy into an array of the right size.
    wide.nodes.resize(std::max(n, 2u) - 1);
    Builder<W> builder(refs, options, pool, wide.nodes);
    builder.buildRoot(builder.decide(root));
    wide.nodes.resize(builder.nodeCount());
    wide.primIndices.resize(n);
    for (uint32_t i = 0; i < n; ++i) wide.primIndices[i] = refs[i].id();
    return wide;
}

template WideBvh<4> buildWideBvh<4>(std::span<const Bounds3f>, const WideBvhBuildOptions&);
template WideBvh<8> buildWideBvh<8>(std::span<const Bounds3f>, const WideBvhBuildOptions&);

}  // namespace rtlab
