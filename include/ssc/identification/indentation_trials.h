#ifndef ssc_identification_indentation_trials_h
#define ssc_identification_indentation_trials_h

#include <array>
#include <string>
#include <vector>

#include <ssc/scenes/identification_parameters.h>

namespace ssc
{
  /**
   * One in vivo probe indentation trial of the MULTIS study
   * (data/multis/README.md): the layer thicknesses under the probe, the
   * largest force and each layer's compression at that force, measured on
   * ultrasound images. Units: mm, N, MPa.
   */
  struct IndentationTrial
  {
    /// Line of the data file (1 = the header), for messages.
    unsigned int line = 0;
    std::string  subject;
    /// Site code, e.g. LA_A (lower arm, anterior).
    std::string site;
    std::string sex;
    /// Age (years) and body-mass index (kg/m^2) of the subject.
    double age = 0;
    double bmi = 0;
    /// Activity level of the subject: 0 sedentary, 1 moderately active,
    /// 2 active (the table's three words).
    unsigned int activity_level = 0;

    double skin_thickness   = 0;
    double fat_thickness    = 0;
    double muscle_thickness = 0;

    /// Probe face area, mm^2 (MaxForce / maxForce_normArea).
    double probe_area = 0;
    double max_force  = 0;

    /// Compressions at max_force over the unloaded thicknesses.
    double skin_strain   = 0;
    double fat_strain    = 0;
    double muscle_strain = 0;

    /// Slope of the force against the total displacement, N/mm.
    double surface_stiffness = 0;

    /// Skin, fat, muscle thickness, mm.
    std::array<double, 3>
    layer_thicknesses() const
    {
      return {{skin_thickness, fat_thickness, muscle_thickness}};
    }

    /// Skin, fat, muscle compressive strain at max_force.
    std::array<double, 3>
    layer_strains() const
    {
      return {{skin_strain, fat_strain, muscle_strain}};
    }

    /// Skin surface to bone, mm.
    double
    total_thickness() const
    {
      return skin_thickness + fat_thickness + muscle_thickness;
    }

    /// The probe's travel at max_force: the sum of the layers'
    /// compressions, mm.
    double
    displacement() const
    {
      return skin_strain * skin_thickness + fat_strain * fat_thickness +
             muscle_strain * muscle_thickness;
    }
  };

  /// The trials of a data file, and the lines skipped for lack of a
  /// measurement.
  struct IndentationData
  {
    std::vector<IndentationTrial> trials;
    /// Lines with an empty (or nan) thickness, force or strain: the study
    /// could not measure them (e.g. no bone on the image).
    std::vector<unsigned int> incomplete_lines;
  };

  /// The range of layer thicknesses (mm) a trial may have: beyond it a
  /// value is a typing or unit error (the MULTIS table: 0.47 to 85 mm).
  constexpr double min_layer_thickness = 0.05;
  constexpr double max_layer_thickness = 300;

  /**
   * Reads the MULTIS per-trial table (comma separated, a header naming the
   * columns; the columns ssc needs are found by name), keeping the trials
   * of @p sites (all if empty). Throws with a message naming the file and
   * line for a row whose field count differs from the header's, a value
   * that is not a number, a thickness outside [min_layer_thickness,
   * max_layer_thickness], a strain outside (-1, 1), a non-positive force or
   * probe area, an empty subject, a second trial of one subject at one
   * site; naming the column for a header without one that ssc needs or
   * with it twice; and if no trial of @p sites remains.
   */
  IndentationData
  read_indentation_trials(const std::string              &filename,
                          const std::vector<std::string> &sites = {});
} // namespace ssc

#endif
