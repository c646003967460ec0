/* The peer of the reader benchmark (issue 30): dynareadout's streaming keyword reader
 * (https://github.com/PucklaJ/dynareadout, key.h) reading the benchmark deck as an application
 * would: every *NODE card's id and coordinates, every *ELEMENT_SPH card's id, part and mass.
 * It validates nothing. Built by bench/run_perf_bench.sh when DYNAREADOUT_SRC names a checkout;
 * not part of the project's build (no dependency of sphdeck).
 *   dynareadout_peer DECK     prints the cards read and a checksum */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "key.h"

typedef struct {
  size_t nodes, particles, other;
  double sum;
} totals_t;

static void on_card(key_parse_info_t info, const char *keyword, card_t *card, size_t index, void *data) {
  totals_t *t = (totals_t *)data;
  (void)info, (void)index;
  if (!card) return;
  if (strcmp(keyword, "NODE") == 0) {
    card_parse_begin(card, 8);
    const long long id = card_parse_int_width(card, 8);
    card_parse_next_width(card, 16);
    const double x = card_parse_float64_width(card, 16);
    card_parse_next_width(card, 16);
    const double y = card_parse_float64_width(card, 16);
    card_parse_next_width(card, 16);
    const double z = card_parse_float64_width(card, 16);
    t->sum += (double)id + x + y + z, ++t->nodes;
  } else if (strcmp(keyword, "ELEMENT_SPH") == 0) {
    card_parse_begin(card, 8);
    const long long id = card_parse_int_width(card, 8);
    card_parse_next_width(card, 8);
    const long long part = card_parse_int_width(card, 8);
    card_parse_next_width(card, 8);
    const double mass = card_parse_float64_width(card, 16);
    t->sum += (double)(id + part) + mass, ++t->particles;
  } else {
    ++t->other;
  }
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: dynareadout_peer DECK\n");
    return 2;
  }
  totals_t t = {0, 0, 0, 0.0};
  key_parse_config_t config = key_default_parse_config();
  char *error = NULL, *warning = NULL;
  key_file_parse_with_callback(argv[1], on_card, &config, &error, &warning, &t, NULL);
  if (error) {
    fprintf(stderr, "dynareadout: %s\n", error);
    free(error);
    return 1;
  }
  free(warning);
  printf("nodes %zu particles %zu other cards %zu checksum %.6e\n", t.nodes, t.particles, t.other, t.sum);
  return 0;
}
