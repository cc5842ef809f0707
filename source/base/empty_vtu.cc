#include <ssc/base/empty_vtu.h>

namespace ssc
{
  void
  write_empty_vtu(std::ostream &out)
  {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
           "<UnstructuredGrid>\n"
           "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">\n"
           "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
           "format=\"ascii\"></DataArray>\n</Points>\n<Cells>\n"
           "<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\"></DataArray>\n"
           "<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\"></DataArray>\n"
           "<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\"></DataArray>\n</Cells>\n</Piece>\n"
           "</UnstructuredGrid>\n</VTKFile>\n";
  }
} // namespace ssc
