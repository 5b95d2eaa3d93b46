// A value shared by its copies until one of them is changed. A scene may hold millions of
// pigments and textures that differ in a colour and share their pattern and finish, most of
// them the defaults: those parts are held once.
#pragma once

#include <memory>
#include <utility>

namespace rayset::tracer {

template <class T>
class CopyOnWrite {
public:
    CopyOnWrite() : value_(default_value()) {}
    CopyOnWrite(T value) : value_(std::make_shared<T>(std::move(value))) {}

    const T& operator*() const { return *value_; }
    const T* operator->() const { return value_.get(); }

    // The value to change, made this copy's own first when another copy shares it. Only the
    // parser changes values, on one thread.
    T& edit() {
        if (value_.use_count() != 1) value_ = std::make_shared<T>(*value_);
        return *value_;
    }

private:
    // One default-constructed value for all: edit() copies it before it is changed.
    static const std::shared_ptr<T>& default_value() {
        static const std::shared_ptr<T> value = std::make_shared<T>();
        return value;
    }

    std::shared_ptr<T> value_;
};

}  // namespace rayset::tracer
