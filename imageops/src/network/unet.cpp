// unet.cpp: loading a UNet and running it through the plan of its size
// (unet.h).
#include "network/unet.h"

#include "network/thread_count.h"
#include "network/unet_plan.h"

#include <utility>

namespace mcdenoise {

UNet::UNet()                           = default;
UNet::~UNet()                          = default;
UNet::UNet(UNet&&) noexcept            = default;
UNet& UNet::operator=(UNet&&) noexcept = default;

bool UNet::load(const std::string& path, std::string& error)
{
    TensorMap tensors;
    if (!read_tza(path, tensors, error))
        return false;
    return load(std::make_shared<const TensorMap>(std::move(tensors)), path, error);
}

bool UNet::load(std::shared_ptr<const TensorMap> tensors, const std::string& source,
                std::string& error)
{
    plan_.reset();
    layout_  = UNetLayout();
    tensors_ = std::move(tensors);
    source_  = source;
    if (read_unet_layout(*tensors_, source_, layout_, error))
        return true;
    tensors_.reset();
    return false;
}

bool UNet::loaded() const { return !layout_.levels.empty(); }

const UNetLayout& UNet::layout() const { return layout_; }

const std::string& UNet::source() const { return source_; }

UNetPlan* UNet::plan_for(int height, int width, std::string& error)
{
    if (plan_ && plan_->height() == height && plan_->width() == width)
        return plan_.get();
    plan_.reset();
    auto plan = UNetPlan::create(layout_, height, width, error);
    if (!plan || !plan->allocate(error))
        return nullptr;
    plan_ = std::move(plan);
    return plan_.get();
}

void UNet::release_plan() { plan_.reset(); }

size_t UNet::working_bytes(int height, int width, std::string& error)
{
    if (!loaded()) {
        error = "no network is loaded";
        return 0;
    }
    const auto plan = UNetPlan::create(layout_, height, width, error);
    return plan ? plan->working_bytes() : 0;
}

bool UNet::run(const float* input, int height, int width, float* output, int nthreads,
               std::string& error)
{
    if (!loaded()) {
        error = "no network is loaded";
        return false;
    }
    ScopedThreadCount threads(nthreads);
    UNetPlan* plan = plan_for(height, width, error);
    return plan && plan->run(input, output, error);
}

}  // namespace mcdenoise
