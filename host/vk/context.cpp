// Instance and device creation: Vulkan 1.2, one compute queue, nothing else.
#include "vk/context.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "error.h"
#include "vk/device_requirements.h"
#include "vk/lavapipe_environment.h"

namespace vkmc::vk {

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS)
    throw Error(std::string("Vulkan call failed: ") + what + " (VkResult " + std::to_string(result) + ")");
}

namespace {

VkInstance createInstance() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "vkmc";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  if (vkCreateInstance(&ici, nullptr, &instance) != VK_SUCCESS)
    throw Error("no Vulkan 1.2 instance (is a Vulkan driver such as mesa-vulkan-drivers installed?)");
  return instance;
}

// The device asked for (options, else VKMC_DEVICE), else the first discrete GPU; under mpirun with several on a
// host, each rank of the host its own, round robin by the launcher's local rank.
VkPhysicalDevice pickPhysicalDevice(VkInstance instance, const ContextOptions& options) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  if (devices.empty()) throw Error("no Vulkan device found");
  int index = options.deviceIndex;
  if (const char* env = std::getenv("VKMC_DEVICE"); env && index < 0) index = std::atoi(env);
  if (index >= static_cast<int>(devices.size())) throw Error("device index " + std::to_string(index) + " out of range");
  if (index >= 0) return devices[index];
  std::vector<int> discrete;
  for (size_t i = 0; i < devices.size(); ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devices[i], &p);
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) discrete.push_back(static_cast<int>(i));
  }
  int localRank = 0;
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID", "SLURM_LOCALID"})
    if (const char* env = std::getenv(name)) {
      localRank = std::max(0, std::atoi(env));
      break;
    }
  return devices[discrete.empty() ? 0 : discrete[size_t(localRank) % discrete.size()]];
}

// Float atomics (VK_EXT_shader_atomic_float) let split light samples add into one path; optional.
bool supportsFloatAtomics(VkPhysicalDevice physical) {
  uint32_t extCount = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &extCount, nullptr);
  std::vector<VkExtensionProperties> exts(extCount);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &extCount, exts.data());
  bool hasAtomicExt = false;
  for (const auto& e : exts) hasAtomicExt |= std::string(e.extensionName) == VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME;
  if (!hasAtomicExt) return false;
  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFeatures{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  f2.pNext = &atomicFeatures;
  vkGetPhysicalDeviceFeatures2(physical, &f2);
  return atomicFeatures.shaderBufferFloat32AtomicAdd == VK_TRUE;
}

}  // namespace

// The device's properties and limits, checked against what vkmc's kernels use.
void Context::readDevice() {
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  if (properties_.apiVersion < VK_API_VERSION_1_2)
    throw Error(std::string("device ") + properties_.deviceName + " lacks Vulkan 1.2");
  const DeviceCapabilities caps = queryCapabilities(physical_);
  subgroupSize_ = caps.subgroupSize;
  std::vector<std::string> missing = missingRequirements(caps);
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : "; ") + m;
    throw Error(std::string("device ") + properties_.deviceName + " lacks what vkmc's kernels use: " + list);
  }
  VkPhysicalDeviceMaintenance3Properties m3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &m3};
  vkGetPhysicalDeviceProperties2(physical_, &p2);
  maxAllocationBytes_ = m3.maxMemoryAllocationSize;
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  for (uint32_t i = 0; i < count; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
      queueFamily_ = i;
      timestampBits_ = families[i].timestampValidBits;
      return;
    }
  throw Error("device has no compute queue");
}

Context::Context(const ContextOptions& options) {
  prepareLavapipeEnvironment();  // before lavapipe reads it at the first instance
  instance_ = createInstance();
  physical_ = pickPhysicalDevice(instance_, options);
  readDevice();
  floatAtomics_ = supportsFloatAtomics(physical_);
  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT enableAtomics{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  enableAtomics.shaderBufferFloat32AtomicAdd = VK_TRUE;
  const char* atomicExtName = VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME;
  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = queueFamily_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  VkPhysicalDeviceFeatures enabled{};
  enabled.shaderInt64 = VK_TRUE;  // checked by readDevice (missingRequirements)
  dci.pEnabledFeatures = &enabled;
  if (floatAtomics_) {
    dci.enabledExtensionCount = 1;
    dci.ppEnabledExtensionNames = &atomicExtName;
    dci.pNext = &enableAtomics;
  }
  check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = queueFamily_;
  check(vkCreateCommandPool(device_, &pci, nullptr, &pool_), "vkCreateCommandPool");
  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(vkCreateFence(device_, &fci, nullptr, &fence_), "vkCreateFence");
}

Context::~Context() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags want : {required | preferred, required}) {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  throw Error("no suitable Vulkan memory type");
}

VkCommandBuffer Context::beginCommands() {
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool_;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  check(vkAllocateCommandBuffers(device_, &ai, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  return cmd;
}

void Context::submitAndWait(VkCommandBuffer cmd) {
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  check(vkQueueSubmit(queue_, 1, &si, fence_), "vkQueueSubmit");
  check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  check(vkResetFences(device_, 1, &fence_), "vkResetFences");
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
}

void Context::runCommands(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBuffer cmd = beginCommands();
  record(cmd);
  submitAndWait(cmd);
}

}  // namespace vkmc::vk
