#pragma once
// A results.nc opened with the netCDF C API for a test to read: dimensions, variables, their
// attributes and values; every call checked.
#include <netcdf.h>

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace cablefilm_test {

// An open results file, closed at the end of the scope; every call checked.
class NcFile {
 public:
  explicit NcFile(const std::filesystem::path& p) {
    const int status = nc_open(p.c_str(), NC_NOWRITE, &id_);
    if (status != NC_NOERR) throw std::runtime_error(p.string() + ": " + nc_strerror(status));
  }
  ~NcFile() { nc_close(id_); }
  int id() const { return id_; }
  size_t Dim(const char* name) const {
    int dim = -1;
    size_t n = 0;
    Ok(nc_inq_dimid(id_, name, &dim), name);
    Ok(nc_inq_dimlen(id_, dim, &n), name);
    return n;
  }
  int Var(const char* name) const {
    int var = -1;
    Ok(nc_inq_varid(id_, name, &var), name);
    return var;
  }
  std::string Attr(int var, const char* name) const {
    size_t n = 0;
    if (nc_inq_attlen(id_, var, name, &n) != NC_NOERR) return "(no " + std::string(name) + ")";
    std::string text(n, '\0');
    Ok(nc_get_att_text(id_, var, name, text.data()), name);
    return text;
  }
  std::string Attr(const char* var, const char* name) const { return Attr(Var(var), name); }
  std::vector<double> Values(const char* name) const {
    const int var = Var(name);
    int ndims = 0;
    Ok(nc_inq_varndims(id_, var, &ndims), name);
    std::vector<int> dims(static_cast<size_t>(ndims));
    Ok(nc_inq_vardimid(id_, var, dims.data()), name);
    size_t n = 1;
    for (int d : dims) {
      size_t len = 0;
      Ok(nc_inq_dimlen(id_, d, &len), name);
      n *= len;
    }
    std::vector<double> v(n);
    Ok(nc_get_var_double(id_, var, v.data()), name);
    return v;
  }
  // The dimension names of a variable, comma separated.
  std::string Dims(const char* name) const {
    const int var = Var(name);
    int ndims = 0;
    Ok(nc_inq_varndims(id_, var, &ndims), name);
    std::vector<int> dims(static_cast<size_t>(ndims));
    Ok(nc_inq_vardimid(id_, var, dims.data()), name);
    std::string out;
    for (int d : dims) {
      char dim_name[NC_MAX_NAME + 1];
      Ok(nc_inq_dimname(id_, d, dim_name), name);
      out += (out.empty() ? "" : ",") + std::string(dim_name);
    }
    return out;
  }

 private:
  static void Ok(int status, const char* what) {
    if (status != NC_NOERR) throw std::runtime_error(std::string(what) + ": " + nc_strerror(status));
  }
  int id_ = -1;
};

}  // namespace cablefilm_test
