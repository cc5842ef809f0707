#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.templates.h>

#include <sstream>

#include <ssc/base/collective_error.h>

namespace ssc
{
  namespace
  {
    /// The additional information of a deal.II exception.
    std::string
    message_of(const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return info.str();
    }
  } // namespace


  void
  run_collectively(const std::function<void()> &work,
                   const MPI_Comm               communicator)
  {
    std::string message;
    bool        failed = false;
    try
      {
        work();
      }
    catch (const ExceptionBase &e)
      {
        failed  = true;
        message = message_of(e);
      }
    catch (const std::exception &e)
      {
        failed  = true;
        message = e.what();
      }
    if (Utilities::MPI::max(failed ? 1u : 0u, communicator) == 0u)
      return;
    const std::vector<std::string> messages =
      Utilities::MPI::all_gather(communicator, failed ? message : "");
    for (const std::string &m : messages)
      if (!m.empty())
        AssertThrow(false, ExcMessage(m));
    AssertThrow(false, ExcMessage("An error without a message on some rank."));
  }
} // namespace ssc
