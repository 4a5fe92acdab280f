#include "engine/map/geotiff.h"

#include <mutex>
#include <random>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

// The city frame of an Argoverse map: a local Cartesian frame in metres, x east, y north.
const char* const kCityFrameWkt =
    "LOCAL_CS[\"Argoverse city frame\",LOCAL_DATUM[\"city\",32767],UNIT[\"metre\",1,"
    "AUTHORITY[\"EPSG\",\"9001\"]],AXIS[\"Easting\",EAST],AXIS[\"Northing\",NORTH]]";

void registerGdal() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// Captures GDAL's error messages on this thread instead of printing them to stderr.
class QuietGdal {
 public:
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  static std::string lastMessage() {
    const char* msg = CPLGetLastErrorMsg();
    return msg && *msg ? std::string(": ") + msg : std::string();
  }
};

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(GDALDataset::ToHandle(d)); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

template <typename T>
void writeTo(const fs::path& file, const fs::path& reported, const GeoRaster<T>& raster, GDALDataType type,
             const char* predictor) {
  if (raster.rows <= 0 || raster.cols <= 0 || raster.values.size() != size_t(raster.rows) * size_t(raster.cols)) {
    throw Error(reported.string(), "raster size does not match its values");
  }
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (!driver) throw Error(reported.string(), "GDAL has no GTiff driver");
  char** options = nullptr;
  options = CSLSetNameValue(options, "TILED", "YES");
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  options = CSLSetNameValue(options, "PREDICTOR", predictor);
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  Dataset ds(driver->Create(file.c_str(), raster.cols, raster.rows, 1, type, options));
  CSLDestroy(options);
  if (!ds) throw Error(reported.string(), "cannot create GeoTIFF" + QuietGdal::lastMessage());
  GeoTransform gt = raster.transform;
  GDALRasterBand* band = ds->GetRasterBand(1);
  bool ok = ds->SetGeoTransform(gt.data()) == CE_None && ds->SetProjection(kCityFrameWkt) == CE_None;
  if (raster.noData) ok = ok && band->SetNoDataValue(*raster.noData) == CE_None;
  if (!raster.description.empty()) band->SetDescription(raster.description.c_str());
  ok = ok && band->RasterIO(GF_Write, 0, 0, raster.cols, raster.rows, const_cast<T*>(raster.values.data()),
                            raster.cols, raster.rows, type, 0, 0) == CE_None;
  ds.reset();  // flushes and closes; failures surface as GDAL errors
  ok = ok && CPLGetLastErrorType() < CE_Failure;
  if (!ok) throw Error(reported.string(), "cannot write GeoTIFF" + QuietGdal::lastMessage());
}

template <typename T>
void writeAtomically(const fs::path& path, const GeoRaster<T>& raster, GDALDataType type, const char* predictor) {
  registerGdal();
  QuietGdal quiet;
  std::random_device rd;
  std::string name = path.filename().string();
  name.insert(0, 1, '.');
  name.append(".tmp").append(std::to_string(rd()));
  const fs::path tmp = path.parent_path() / name;
  std::error_code ec;
  try {
    writeTo(tmp, path, raster, type, predictor);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error(path.string(), "cannot rename temporary file into place: " + ec.message());
  }
}

}  // namespace

GeoTransform northUpTransform(const GridGeometry& grid) {
  return {grid.origin.x(), grid.resolution, 0.0, grid.origin.y() + grid.rows * grid.resolution, 0.0,
          -grid.resolution};
}

void writeGeoTiff(const fs::path& path, const GeoRaster<uint8_t>& raster) {
  writeAtomically(path, raster, GDT_Byte, "2");
}

void writeGeoTiff(const fs::path& path, const GeoRaster<float>& raster) {
  writeAtomically(path, raster, GDT_Float32, "3");
}

GeoRaster<float> readGeoTiffFloat(const fs::path& path) {
  registerGdal();
  QuietGdal quiet;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string(), "file not found");
  Dataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw Error(path.string(), "not a raster GDAL can read" + QuietGdal::lastMessage());
  if (ds->GetRasterCount() < 1) throw Error(path.string(), "raster has no band");
  GeoRaster<float> out;
  out.cols = ds->GetRasterXSize();
  out.rows = ds->GetRasterYSize();
  if (out.cols <= 0 || out.rows <= 0 || double(out.cols) * out.rows > 1e9) {
    throw Error(path.string(), "implausible raster size " + std::to_string(out.cols) + " x " + std::to_string(out.rows));
  }
  if (ds->GetGeoTransform(out.transform.data()) != CE_None) throw Error(path.string(), "raster has no geotransform");
  GDALRasterBand* band = ds->GetRasterBand(1);
  int hasNoData = 0;
  const double noData = band->GetNoDataValue(&hasNoData);
  if (hasNoData) out.noData = noData;
  if (const char* d = band->GetDescription()) out.description = d;
  out.values.resize(size_t(out.rows) * size_t(out.cols));
  if (band->RasterIO(GF_Read, 0, 0, out.cols, out.rows, out.values.data(), out.cols, out.rows, GDT_Float32, 0, 0) !=
      CE_None) {
    throw Error(path.string(), "cannot read band 1" + QuietGdal::lastMessage());
  }
  return out;
}

}  // namespace hdprior
