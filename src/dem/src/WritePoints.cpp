// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/WritePoints.hpp"

#include <atomic>

namespace dem {

namespace {
std::atomic<WritePointHook> installedHook{nullptr};
}

WritePointHook setWritePointHook(WritePointHook hook)
{
    return installedHook.exchange(hook);
}

void atWritePoint(const char* point)
{
    if (const WritePointHook hook = installedHook.load(std::memory_order_relaxed)) hook(point);
}

} // namespace dem
