// unet_plan.cpp: a UNet on oneDNN for one image size (unet_plan.h).
#include "network/unet_plan.h"

#include <oneapi/dnnl/dnnl.hpp>

#include <algorithm>
#include <new>
#include <unordered_map>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace mcdenoise {

namespace {

using dnnl::memory;

/// Allocates straight from the kernel (an anonymous mmap): page-aligned,
/// which oneDNN needs (its kernels take their buffers as 64-byte aligned,
/// and the nearest resampling on large images faults on a buffer that is
/// not), and given back to the kernel when the plan goes, whatever the
/// process's malloc settings: mcdtool keeps freed heap memory for its next
/// frame, which left one network's arena of gigabytes beside the next's.
template<class T>
struct MappedAllocator {
    using value_type = T;

    MappedAllocator() = default;
    template<class U>
    MappedAllocator(const MappedAllocator<U>&)
    {
    }
    T* allocate(size_t n)
    {
        void* p = mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED)
            throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) { munmap(p, n * sizeof(T)); }
    template<class U>
    bool operator==(const MappedAllocator<U>&) const
    {
        return true;
    }
    template<class U>
    bool operator!=(const MappedAllocator<U>&) const
    {
        return false;
    }
};

int round_up(int value, int multiple) { return (value + multiple - 1) / multiple * multiple; }

/// A range of whole channel blocks of one level's tensor in the arena:
/// `channels` (a multiple of the block) channels from float `offset`.
struct Chunk {
    size_t offset = 0;
    int channels  = 0;
    int level     = 0;
};

/// A run of input channels of a convolution: `channels` of the weights'
/// inputs, stored in `padded` channels of the source.
struct Segment {
    int channels = 0;
    int padded   = 0;
};

/// One step of the network, in the order they run.
struct Op {
    enum class Kind { conv, pool, upsample } kind = Kind::conv;
    const UNetConv* conv = nullptr;
    std::vector<Segment> inputs;  // conv only: how its input channels are stored
    Chunk src, dst;
    dnnl::primitive_desc pd;
};

memory::format_tag blocked_tag(int block)
{
    return block == 16 ? memory::format_tag::nChw16c : memory::format_tag::nChw8c;
}

/// The weights of `conv` padded with zeros to the stored channels: inputs
/// laid out as `inputs` says, outputs to `out_padded`; oihw.
std::vector<float> padded_weights(const UNetConv& conv, const std::vector<Segment>& inputs,
                                  int out_padded)
{
    int in_padded = 0;
    for (const Segment& s : inputs)
        in_padded += s.padded;
    std::vector<float> padded(size_t(out_padded) * size_t(in_padded) * 9, 0.0f);
    for (int o = 0; o < conv.out_channels; ++o) {
        int logical = 0, stored = 0;
        for (const Segment& s : inputs) {
            for (int i = 0; i < s.channels; ++i)
                std::copy_n(conv.weight->data() + (size_t(o) * conv.in_channels + logical + i) * 9, 9,
                            padded.data() + (size_t(o) * in_padded + stored + i) * 9);
            logical += s.channels;
            stored += s.padded;
        }
    }
    return padded;
}

}  // namespace

int unet_channel_block()
{
    const unsigned isa = unsigned(dnnl::get_effective_cpu_isa());
    const unsigned avx512 = unsigned(dnnl::cpu_isa::avx512_core);
    return (isa & avx512) == avx512 ? 16 : 8;
}

struct UNetPlan::Impl {
    const UNetLayout layout;  // a copy: the weights it points to outlive the plan
    int height = 0, width = 0, block = 16;
    dnnl::engine engine { dnnl::engine::kind::cpu, 0 };
    std::vector<Op> ops;
    Chunk input_chunk, output_chunk;
    size_t arena_floats = 0, scratchpad_bytes = 0, weight_bytes = 0;

    // Set by allocate(); every chunk's offset is a whole number of channel
    // blocks of pixels, so every chunk is as aligned as the arena.
    std::vector<float, MappedAllocator<float>> arena;
    std::vector<uint8_t, MappedAllocator<uint8_t>> scratchpad;
    std::vector<dnnl::primitive> primitives;
    std::vector<std::unordered_map<int, memory>> arguments;
    std::vector<memory> weights;

    Impl(const UNetLayout& layout_, int height_, int width_)
        : layout(layout_), height(height_), width(width_), block(unet_channel_block())
    {
    }

    int level_height(int level) const { return height >> level; }
    int level_width(int level) const { return width >> level; }
    int padded(int channels) const { return round_up(channels, block); }

    /// A new chunk of `channels` (padded) channels at `level` in the arena.
    Chunk reserve(int level, int channels)
    {
        Chunk chunk { arena_floats, padded(channels), level };
        arena_floats += size_t(chunk.channels) * level_height(level) * level_width(level);
        return chunk;
    }
    /// The part of `chunk` from channel `first` on (`first` padded).
    Chunk tail(const Chunk& chunk, int first) const
    {
        return { chunk.offset + size_t(first) * level_height(chunk.level) * level_width(chunk.level),
                 chunk.channels - first, chunk.level };
    }
    /// `channels` (padded) channels at `level` from float `offset` of a
    /// scratch buffer, which every level reuses.
    Chunk scratch_chunk(size_t offset, int level, int channels) const
    {
        return { offset, padded(channels), level };
    }

    memory::desc desc(const Chunk& chunk) const
    {
        return memory::desc({ 1, chunk.channels, level_height(chunk.level), level_width(chunk.level) },
                            memory::data_type::f32, blocked_tag(block));
    }

    dnnl::primitive_attr attributes(bool relu) const
    {
        dnnl::primitive_attr attr;
        attr.set_scratchpad_mode(dnnl::scratchpad_mode::user);
        if (relu) {
            dnnl::post_ops post;
            post.append_eltwise(1.0f, dnnl::algorithm::eltwise_relu, 0.0f, 0.0f);
            attr.set_post_ops(post);
        }
        return attr;
    }

    void add_conv(const UNetConv& conv, std::vector<Segment> inputs, const Chunk& src, const Chunk& dst)
    {
        Op op;
        op.kind   = Op::Kind::conv;
        op.conv   = &conv;
        op.inputs = std::move(inputs);
        op.src    = src;
        op.dst    = dst;
        const memory::desc weights({ dst.channels, src.channels, 3, 3 }, memory::data_type::f32,
                                   memory::format_tag::any);
        const memory::desc bias({ dst.channels }, memory::data_type::f32, memory::format_tag::x);
        const dnnl::convolution_forward::desc d(dnnl::prop_kind::forward_inference,
                                                dnnl::algorithm::convolution_direct, desc(src), weights,
                                                bias, desc(dst), { 1, 1 }, { 1, 1 }, { 1, 1 });
        op.pd = dnnl::convolution_forward::primitive_desc(d, attributes(true), engine);
        weight_bytes += op.pd.weights_desc().get_size() + bias.get_size();
        add(std::move(op));
    }

    void add_pool(const Chunk& src, const Chunk& dst)
    {
        Op op;
        op.kind = Op::Kind::pool;
        op.src  = src;
        op.dst  = dst;
        const dnnl::pooling_forward::desc d(dnnl::prop_kind::forward_inference,
                                            dnnl::algorithm::pooling_max, desc(src), desc(dst), { 2, 2 },
                                            { 2, 2 }, { 0, 0 }, { 0, 0 });
        op.pd = dnnl::pooling_forward::primitive_desc(d, attributes(false), engine);
        add(std::move(op));
    }

    void add_upsample(const Chunk& src, const Chunk& dst)
    {
        Op op;
        op.kind = Op::Kind::upsample;
        op.src  = src;
        op.dst  = dst;
        const dnnl::resampling_forward::desc d(dnnl::prop_kind::forward_inference,
                                               dnnl::algorithm::resampling_nearest, desc(src), desc(dst));
        op.pd = dnnl::resampling_forward::primitive_desc(d, attributes(false), engine);
        add(std::move(op));
    }

    void add(Op op)
    {
        scratchpad_bytes = std::max(scratchpad_bytes, op.pd.scratchpad_desc().get_size());
        ops.push_back(std::move(op));
    }

    /// Lays out every buffer and primitive.
    void build()
    {
        const int levels = int(layout.levels.size());
        // Each level's input: inside its decoder's concatenation [upsampled,
        // input], or alone on the last level.
        std::vector<Chunk> concat(levels), level_input(levels);
        for (int level = 0; level < levels; ++level) {
            const int in = layout.level_input_channels(level);
            if (level + 1 < levels) {
                const int up   = padded(layout.upsampled_channels(level));
                concat[level]  = reserve(level, up + padded(in));
                level_input[level] = tail(concat[level], up);
            } else {
                level_input[level] = reserve(level, in);
            }
        }
        // Two scratch buffers, shared by every level: as large as the largest
        // convolution output of any level.
        size_t scratch_floats = 0;
        for (int level = 0; level < levels; ++level)
            for (const auto* side : { &layout.levels[level].encoder, &layout.levels[level].decoder })
                for (const UNetConv& conv : *side)
                    scratch_floats = std::max(scratch_floats, size_t(padded(conv.out_channels))
                                                                  * level_height(level) * level_width(level));
        const size_t scratch[2] = { arena_floats, arena_floats + scratch_floats };
        arena_floats += 2 * scratch_floats;

        Chunk current;
        int next_scratch = 0;
        auto run_convs = [&](const std::vector<UNetConv>& convs, int level, Chunk src,
                             std::vector<Segment> inputs) {
            for (const UNetConv& conv : convs) {
                const Chunk dst = scratch_chunk(scratch[next_scratch], level, conv.out_channels);
                next_scratch    = 1 - next_scratch;
                add_conv(conv, std::move(inputs), src, dst);
                src    = dst;
                inputs = { { conv.out_channels, dst.channels } };
            }
            return src;
        };

        input_chunk = level_input[0];
        for (int level = 0; level < levels; ++level) {
            const int in = layout.level_input_channels(level);
            current      = run_convs(layout.levels[level].encoder, level, level_input[level],
                                     { { in, padded(in) } });
            if (level + 1 < levels)
                add_pool(current, level_input[level + 1]);
        }
        for (int level = levels - 2; level >= 0; --level) {
            const int up = layout.upsampled_channels(level);
            const int in = layout.level_input_channels(level);
            add_upsample(current, { concat[level].offset, padded(up), level });
            current = run_convs(layout.levels[level].decoder, level, concat[level],
                                { { up, padded(up) }, { in, padded(in) } });
        }
        output_chunk = current;
    }

    void allocate()
    {
        arena.assign(arena_floats, 0.0f);
        scratchpad.assign(scratchpad_bytes, 0);
        dnnl::stream stream(engine);
        const memory scratch_memory(dnnl::memory::desc({ memory::dim(scratchpad.size()) },
                                                       memory::data_type::u8, memory::format_tag::x),
                                    engine, scratchpad.data());
        for (const Op& op : ops) {
            std::unordered_map<int, memory> args;
            args[DNNL_ARG_SRC]        = memory(desc(op.src), engine, arena.data() + op.src.offset);
            args[DNNL_ARG_DST]        = memory(desc(op.dst), engine, arena.data() + op.dst.offset);
            args[DNNL_ARG_SCRATCHPAD] = scratch_memory;
            if (op.kind == Op::Kind::conv) {
                auto plain = padded_weights(*op.conv, op.inputs, op.dst.channels);
                const memory::desc plain_desc({ op.dst.channels, op.src.channels, 3, 3 },
                                              memory::data_type::f32, memory::format_tag::oihw);
                memory user(plain_desc, engine, plain.data());
                memory reordered(op.pd.weights_desc(), engine);
                dnnl::reorder(user, reordered).execute(stream, user, reordered);
                std::vector<float> bias(size_t(op.dst.channels), 0.0f);
                std::copy(op.conv->bias->begin(), op.conv->bias->end(), bias.begin());
                memory bias_memory(memory::desc({ op.dst.channels }, memory::data_type::f32,
                                                memory::format_tag::x),
                                   engine);
                std::copy(bias.begin(), bias.end(), static_cast<float*>(bias_memory.get_data_handle()));
                stream.wait();
                args[DNNL_ARG_WEIGHTS] = reordered;
                args[DNNL_ARG_BIAS]    = bias_memory;
                weights.push_back(reordered);
                weights.push_back(bias_memory);
            }
            primitives.emplace_back(op.pd);
            arguments.push_back(std::move(args));
        }
    }

    /// Writes the planar `input` into the blocked input chunk, padding
    /// channels with zeros.
    void pack_input(const float* input)
    {
        const size_t pixels = size_t(height) * width;
        const int channels  = layout.input_channels;
        float* dst          = arena.data() + input_chunk.offset;
        std::fill_n(dst, size_t(input_chunk.channels) * pixels, 0.0f);
        for (int c = 0; c < channels; ++c) {
            float* block_start = dst + size_t(c / block) * pixels * block + c % block;
            const float* plane = input + size_t(c) * pixels;
            for (size_t p = 0; p < pixels; ++p)
                block_start[p * block] = plane[p];
        }
    }

    /// Reads the first 3 channels of the blocked output chunk into planes.
    void unpack_output(float* output) const
    {
        const size_t pixels = size_t(height) * width;
        const float* src    = arena.data() + output_chunk.offset;
        for (int c = 0; c < unet_output_channels; ++c) {
            const float* block_start = src + size_t(c / block) * pixels * block + c % block;
            float* plane             = output + size_t(c) * pixels;
            for (size_t p = 0; p < pixels; ++p)
                plane[p] = block_start[p * block];
        }
    }

    void run(const float* input, float* output)
    {
        pack_input(input);
        dnnl::stream stream(engine);
        for (size_t i = 0; i < primitives.size(); ++i)
            primitives[i].execute(stream, arguments[i]);
        stream.wait();
        unpack_output(output);
    }
};

UNetPlan::UNetPlan(std::unique_ptr<Impl> impl)
    : impl_(std::move(impl))
{
}

UNetPlan::~UNetPlan() = default;

std::unique_ptr<UNetPlan> UNetPlan::create(const UNetLayout& layout, int height, int width,
                                           std::string& error)
{
    if (height <= 0 || width <= 0 || height % unet_alignment || width % unet_alignment) {
        error = "the network runs on sides that are positive multiples of "
                + std::to_string(unet_alignment) + ", not " + std::to_string(width) + "x"
                + std::to_string(height);
        return nullptr;
    }
    try {
        auto impl = std::make_unique<Impl>(layout, height, width);
        impl->build();
        return std::unique_ptr<UNetPlan>(new UNetPlan(std::move(impl)));
    } catch (const dnnl::error& e) {
        error = std::string("oneDNN cannot plan the network at ") + std::to_string(width) + "x"
                + std::to_string(height) + ": " + e.what();
    }
    return nullptr;
}

int UNetPlan::height() const { return impl_->height; }
int UNetPlan::width() const { return impl_->width; }

size_t UNetPlan::working_bytes() const
{
    return impl_->arena_floats * sizeof(float) + impl_->scratchpad_bytes + impl_->weight_bytes;
}

bool UNetPlan::allocate(std::string& error)
{
    try {
        impl_->allocate();
        return true;
    } catch (const dnnl::error& e) {
        error = std::string("oneDNN failed preparing the network: ") + e.what();
    } catch (const std::bad_alloc&) {
        error = "out of memory preparing the network for " + std::to_string(impl_->width) + "x"
                + std::to_string(impl_->height) + " pixels ("
                + std::to_string(working_bytes() >> 20) + " MB)";
    }
    impl_->arena      = {};
    impl_->scratchpad = {};
    impl_->primitives.clear();
    impl_->arguments.clear();
    return false;
}

bool UNetPlan::run(const float* input, float* output, std::string& error)
{
    try {
        impl_->run(input, output);
        return true;
    } catch (const dnnl::error& e) {
        error = std::string("oneDNN failed running the network: ") + e.what();
    }
    return false;
}

}  // namespace mcdenoise
