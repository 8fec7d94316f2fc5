#pragma once
#include <map>
#include <memory>
#include <string>
#include <typeinfo>

namespace granpipe {

// Expensive per-frame intermediates (neighbour lists, the contact graph, a
// triangulation) computed once and shared by every analyzer that asks for them.
// Cleared by the runner before each frame. The key must name the quantity and every
// parameter it depends on.
class FrameCache {
 public:
  template <class T, class Compute>
  const T& get(const std::string& key, Compute&& compute) {
    // The type is part of the key so that two analyzers can never read one item as
    // two different types.
    const std::string full_key = key + '#' + typeid(T).name();
    auto it = items_.find(full_key);
    if (it == items_.end()) {
      it = items_.emplace(full_key, std::shared_ptr<void>(std::make_shared<T>(compute()))).first;
    }
    return *static_cast<const T*>(it->second.get());
  }
  void clear() { items_.clear(); }

 private:
  std::map<std::string, std::shared_ptr<void>> items_;
};

}  // namespace granpipe
