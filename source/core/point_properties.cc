// PointLayout: the optional properties of a scene's points, laid out from
// the declarations of the bodies' materials and the scene's couplings.
#include <impm/core/point_properties.h>

#include <algorithm>
#include <stdexcept>

namespace impm
{
  namespace
  {
    /** "name(n)" for a declaration. */
    std::string
    describe(const PointField &field)
    {
      return field.name + "(" + std::to_string(field.n_components) + ")";
    }
  } // namespace



  void
  PointLayout::initialize(const unsigned int              n_fixed,
                          const std::vector<PointFields> &material_fields,
                          const PointFields              &coupling_fields)
  {
    n_total               = n_fixed;
    body                  = material_fields.size() > 1 ? n_total++ : absent;
    material_first        = n_total;
    material_declarations = material_fields;
    material_sizes.assign(material_fields.size(), 0);
    writable.clear();
    couplings.clear();

    const auto written_field = [this](const PointField &field) {
      for (auto &known : writable)
        if (known.name == field.name)
          {
            if (known.n_components != field.n_components)
              throw std::logic_error(
                "Point field '" + field.name + "' is declared with " +
                std::to_string(known.n_components) + " and with " +
                std::to_string(field.n_components) + " entries.");
            return &known;
          }
      writable.push_back(
        {field.name,
         field.n_components,
         std::vector<unsigned int>(
           std::max<std::size_t>(material_sizes.size(), 1), absent)});
      return &writable.back();
    };

    unsigned int longest = 0;
    for (unsigned int b = 0; b < material_fields.size(); ++b)
      {
        for (const PointField &field : material_fields[b])
          {
            if (field.written)
              written_field(field)->first_by_body[b] =
                material_first + material_sizes[b];
            material_sizes[b] += field.n_components;
          }
        longest = std::max(longest, material_sizes[b]);
      }
    n_total += longest;

    for (const PointField &field : coupling_fields)
      {
        const bool material_field =
          std::any_of(writable.begin(),
                      writable.end(),
                      [&field](const WrittenField &known) {
                        return known.name == field.name;
                      });
        if (coupling_field(field.name) != absent || material_field)
          throw std::logic_error("The point field '" + field.name +
                                 "' is declared twice.");
        couplings.emplace_back(field, n_total);
        if (field.written)
          {
            auto &entry = *written_field(field);
            std::fill(entry.first_by_body.begin(),
                      entry.first_by_body.end(),
                      n_total);
          }
        n_total += field.n_components;
      }
  }



  unsigned int
  PointLayout::coupling_field(const std::string &name) const
  {
    for (const auto &[field, first] : couplings)
      if (field.name == name)
        return first;
    return absent;
  }



  unsigned int
  PointLayout::coupling_field_entries(const std::string &name) const
  {
    for (const auto &[field, first] : couplings)
      if (field.name == name)
        return field.n_components;
    return 0;
  }



  std::string
  PointLayout::description() const
  {
    std::string text = std::to_string(n_total) + " properties";
    if (body != absent)
      text += "; body";
    for (unsigned int b = 0; b < material_declarations.size(); ++b)
      if (!material_declarations[b].empty())
        {
          text += "; body " + std::to_string(b + 1) + ":";
          for (const PointField &field : material_declarations[b])
            text += " " + describe(field);
        }
    for (const auto &coupling : couplings)
      text += "; " + describe(coupling.first);
    return text;
  }
} // namespace impm
