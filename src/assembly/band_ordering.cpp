#include "assembly/band_ordering.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/cuthill_mckee_ordering.hpp>

namespace pound::assembly {

namespace {

using Graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                          boost::property<boost::vertex_color_t, boost::default_color_type,
                                          boost::property<boost::vertex_degree_t, int>>>;
using Vertex = boost::graph_traits<Graph>::vertex_descriptor;

// An edge for each nonzero entry below the diagonal.
Graph graph_of(const Eigen::SparseMatrix<double>& matrix) {
  Graph graph(static_cast<std::size_t>(matrix.rows()));
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it)
      if (it.row() > col && it.value() != 0.0)
        boost::add_edge(static_cast<Vertex>(it.row()), static_cast<Vertex>(col), graph);
  return graph;
}

}  // namespace

Components connected_components(const Eigen::SparseMatrix<double>& matrix) {
  const Graph graph = graph_of(matrix);
  Components components;
  components.of.resize(boost::num_vertices(graph));
  components.count = boost::connected_components(graph, components.of.data());
  return components;
}

std::vector<Index> reverse_cuthill_mckee(const Eigen::SparseMatrix<double>& matrix) {
  Graph graph = graph_of(matrix);
  std::vector<Vertex> reversed(boost::num_vertices(graph));
  boost::cuthill_mckee_ordering(graph, reversed.rbegin(), boost::get(boost::vertex_color, graph),
                                boost::make_degree_map(graph));
  return {reversed.begin(), reversed.end()};
}

Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& matrix,
                                     const std::vector<Index>& order) {
  std::vector<Index> position(static_cast<std::size_t>(matrix.rows()), -1);  // -1: left out
  for (std::size_t k = 0; k < order.size(); ++k)
    position[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it) {
      const Index row = position[static_cast<std::size_t>(it.row())],
                  column = position[static_cast<std::size_t>(col)];
      if (row >= 0 && column >= 0) entries.emplace_back(row, column, it.value());
    }
  const auto size = static_cast<Index>(order.size());
  Eigen::SparseMatrix<double> result(size, size);
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

}  // namespace pound::assembly
