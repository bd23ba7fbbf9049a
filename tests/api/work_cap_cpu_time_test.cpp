// The work cap bounds CPU time: requests that spend their budget where a step costs more than
// it is charged answer 200 or the work-cap 422 within a CPU time no bounded request comes near
// (a wide margin, not a timing).

#include <gtest/gtest.h>

#include <ctime>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "api/handler.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

// A quadratic reaching 3e129 against a
// quartic reaching 1e237, by subdivision. The search spends its budget at the precision
// floor, where each coincidence test projects five points onto the other curve by up to 30
// Gauss-Newton steps: charged as one step, the request would take several times the CPU
// time its units stand for, so the test is charged by its evaluations. Through the API at
// the default limits, by every method: 200 or the work-cap 422, within a CPU time no bounded
// request comes near (a wide margin, not a timing).
TEST(WorkCapCpuTime, CoincidenceTestsAreChargedByTheirEvaluations) {
  const std::string curves =
      R"("curves":[{"points":[[2.0,-2.0],[-1.0,0.0],[-3.2364e+129,-7.0]]},)"
      R"({"points":[[0.0,-0.5],[0.0,7.0],[0.0,1e+237],)"
      R"([9.999999999999996e+236,9.999999999999992e+236],[9.999999999999989e+236,8.0]]}])";
  for (const char* options : {R"("method":"hybrid")", R"("method":"hybrid","fat_curve_degree":2)",
                              R"("method":"bezier-clipping")", R"("method":"subdivision")"}) {
    const std::string body = "{" + curves + "," + options + "}";
    timespec start{}, end{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &start);
    const Reply reply = handle("/intersections", body, Limits{});
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &end);
    const double cpu = static_cast<double>(end.tv_sec - start.tv_sec) +
                       1e-9 * static_cast<double>(end.tv_nsec - start.tv_nsec);
    EXPECT_TRUE(reply.status == 200 || reply.status == 422) << options << ": " << reply.body;
    EXPECT_LT(cpu, 2.0) << options;
  }
}

// One curve of degree 12 whose last nine control points
// are the origin (its first four 1e-323, 6, 8 and 181.74 from it), by subdivision. Most boxes
// next to the diagonal start a Newton run: each Newton iteration is charged as a box and a
// box's cost covers the run's setup, or the search would take more time than its units
// stand for. Through
// the API at the default limits, one curve and /loop-area: 200 or the work-cap 422 within a
// CPU time no bounded request comes near.
TEST(WorkCapCpuTime, NewtonRunsOfTheSelfIntersectionSearchAreCharged) {
  const std::string points =
      R"([[-1e-323,-5e-324],[-1e-323,6.0],[-8.0,-4.0],[-181.74,0.0],[0.0,0.0],[0.0,0.0],)"
      R"([0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0]])";
  const std::pair<const char*, std::string> requests[] = {
      {"/intersections", R"({"curves":[{"points":)" + points + R"(}],"method":"subdivision"})"},
      {"/loop-area", R"({"points":)" + points + "}"}};
  for (const auto& [path, body] : requests) {
    timespec start{}, end{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &start);
    const Reply reply = handle(path, body, Limits{});
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &end);
    const double cpu = static_cast<double>(end.tv_sec - start.tv_sec) +
                       1e-9 * static_cast<double>(end.tv_nsec - start.tv_nsec);
    EXPECT_TRUE(reply.status == 200 || reply.status == 422) << path << ": " << reply.body;
    EXPECT_LT(cpu, 2.0) << path;
  }
}

}  // namespace
}  // namespace bezier::api
