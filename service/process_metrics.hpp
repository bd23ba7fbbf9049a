#pragma once

#include <string>

namespace bezier::service {

/// Prometheus' standard process metrics of this process, read from the kernel when
/// rendered (never on the request path): process_cpu_seconds_total (user + system),
/// process_resident_memory_bytes, process_virtual_memory_bytes, process_open_fds,
/// process_max_fds and process_start_time_seconds (Unix time), with the names, types and
/// meanings the official clients give them. A value the kernel does not give (no /proc)
/// is left out rather than reported as 0.
[[nodiscard]] std::string render_process_metrics();

}  // namespace bezier::service
