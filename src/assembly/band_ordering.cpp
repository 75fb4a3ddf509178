#include "assembly/band_ordering.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/cuthill_mckee_ordering.hpp>

namespace pound::assembly {

std::vector<Index> reverse_cuthill_mckee(const Eigen::SparseMatrix<double>& matrix) {
  using Graph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                            boost::property<boost::vertex_color_t, boost::default_color_type,
                                            boost::property<boost::vertex_degree_t, int>>>;
  using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
  Graph graph(static_cast<std::size_t>(matrix.rows()));
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it)
      if (it.row() > col && it.value() != 0.0)
        boost::add_edge(static_cast<Vertex>(it.row()), static_cast<Vertex>(col), graph);
  std::vector<Vertex> reversed(boost::num_vertices(graph));
  boost::cuthill_mckee_ordering(graph, reversed.rbegin(), boost::get(boost::vertex_color, graph),
                                boost::make_degree_map(graph));
  return {reversed.begin(), reversed.end()};
}

Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& matrix,
                                     const std::vector<Index>& order) {
  std::vector<Index> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    position[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it)
      entries.emplace_back(position[static_cast<std::size_t>(it.row())],
                           position[static_cast<std::size_t>(col)], it.value());
  Eigen::SparseMatrix<double> result(matrix.rows(), matrix.cols());
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

}  // namespace pound::assembly
