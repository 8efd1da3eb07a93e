// Does Fast DDS's DomainParticipant::set_listener(nullptr) return once a discovery callback
// that is running when it is called has ended?
//
// rmw_fastrtps calls it when a process's last ROS node is destroyed. Fast DDS 2.14 waits for
// running callbacks with cv.wait_until(lock, steady_clock::time_point::max(), ...); the PyPI
// wheel (ros-fastrtps 2.14.5, manylinux_2_28: no pthread_cond_clockwait) compiles that wait
// through libstdc++'s conversion to the system clock, the deadline overflows, and the loop
// never releases the mutex the callback needs to finish: a deadlock, at 100 % CPU.
// docs/dev/limits.md has the story; tools/fastdds_check/run.py builds and runs this file.
//
// Exit status: 0 if set_listener returned, 3 if it had not returned 5 s after the callback
// ended (the deadlock), 2 if discovery never happened. Shared memory only: no network.

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

using eprosima::fastdds::dds::DomainParticipant;
using eprosima::fastdds::dds::DomainParticipantFactory;
using eprosima::fastdds::dds::DomainParticipantListener;
using eprosima::fastdds::dds::DomainParticipantQos;
using eprosima::fastdds::dds::PARTICIPANT_QOS_DEFAULT;
using Clock = std::chrono::steady_clock;

static std::atomic<bool> callback_started{false};
static std::atomic<bool> callback_ended{false};
static std::atomic<bool> returned{false};

// Discovering the other participant runs this callback; it stays in it for 300 ms.
struct SlowListener : DomainParticipantListener
{
  void on_participant_discovery(
    DomainParticipant *, eprosima::fastrtps::rtps::ParticipantDiscoveryInfo &&) override
  {
    if (callback_started.exchange(true)) {
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    callback_ended = true;
  }
};

int main(int argc, char ** argv)
{
  const int domain = argc > 1 ? std::atoi(argv[1]) : 0;
  DomainParticipantQos qos = PARTICIPANT_QOS_DEFAULT;
  qos.transport().use_builtin_transports = false;
  qos.transport().user_transports.push_back(
    std::make_shared<eprosima::fastdds::rtps::SharedMemTransportDescriptor>());
  auto * factory = DomainParticipantFactory::get_instance();
  SlowListener listener;
  DomainParticipant * a = factory->create_participant(domain, qos, &listener);
  DomainParticipant * b = factory->create_participant(domain, qos);
  if (a == nullptr || b == nullptr) {
    std::printf("could not create the participants\n");
    return 2;
  }
  const auto give_up = Clock::now() + std::chrono::seconds(10);
  while (!callback_started && Clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (!callback_started) {
    std::printf("the participants never discovered each other\n");
    return 2;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // inside the callback now
  std::thread caller([a] {
      a->set_listener(nullptr);
      returned = true;
    });
  while (!callback_ended) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const auto ended = Clock::now();
  while (!returned && Clock::now() - ended < std::chrono::seconds(5)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (!returned) {
    std::printf(
      "deadlock: set_listener(nullptr) had not returned 5 s after the discovery callback "
      "ended\n");
    std::fflush(stdout);
    _exit(3);  // the caller thread cannot be joined
  }
  caller.join();
  std::printf(
    "set_listener(nullptr) returned %.3f s after the discovery callback ended\n",
    std::chrono::duration<double>(Clock::now() - ended).count());
  factory->delete_participant(b);
  factory->delete_participant(a);
  return 0;
}
