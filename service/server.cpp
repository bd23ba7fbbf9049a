#include "service/server.hpp"

#include "service/httplib_engine.hpp"

namespace bezier::service {

Server::Server(const Config& config, Log log)
    : router_(config, std::move(log)), engine_(std::make_unique<HttplibEngine>(router_)) {}

}  // namespace bezier::service
