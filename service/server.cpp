#include "service/server.hpp"

#include "service/epoll_engine.hpp"
#include "service/httplib_engine.hpp"

namespace bezier::service {

namespace {

std::unique_ptr<HttpEngine> make_engine(Router& router) {
  if (router.config().http_engine == HttpEngineKind::epoll) return std::make_unique<EpollEngine>(router);
  return std::make_unique<HttplibEngine>(router);
}

}  // namespace

Server::Server(const Config& config, Log log) : router_(config, std::move(log)), engine_(make_engine(router_)) {}

}  // namespace bezier::service
