# bench.mk - make bench: the speed and memory benchmarks (bench/, docs/BENCHMARKS.md).

# ---- benchmarks ----
bench: deps
	@$(MAKE) --no-print-directory bench-run
bench-run: $(B)/mmmaze $(B)/mmsim $(B)/bench_flood $(B)/simavr_cycles $(B)/avr/flood.elf \
	$(B)/avr/tick0.elf $(B)/avr/tick100.elf arduino $(B)/clients/board/EncPoll.elf $(B)/clients/board/EncPollEdge.elf $(B)/ode_rows \
	$(B)/armcore_speed $(ARM_TEST_ELFS) client-bulebule
	BENCH_MAZE=$(BENCH_MAZE) bash bench/run.sh
$(B)/armcore_speed: bench/armcore_speed.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@
$(B)/ode_rows: bench/ode_rows.c | deps
	$(CC) -O2 $< $$(pkg-config --cflags --libs ode) -lm -o $@
$(B)/simavr_cycles: bench/simavr_cycles.c | deps
	$(CC) -O2 $< $$(pkg-config --cflags --libs simavr) -o $@
# The AVR flood benchmark's true map: japan2018 from the database, else a
# generated 16x16 from mazes/ (bench/avr_flood.c)
BENCH_MAZE ?= $(firstword $(wildcard $(SHARED)/mazes/classic/japan2018.txt) mazes/gen-16x16-s1.txt)
$(B)/maze_header: bench/maze_header.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@
$(B)/avr/bench_maze.h: $(B)/maze_header $(BENCH_MAZE)
	@mkdir -p $(dir $@)
	$(B)/maze_header $(BENCH_MAZE) > $@.tmp && mv $@.tmp $@
$(B)/avr/flood.elf: bench/avr_flood.c $(B)/avr/bench_maze.h $(FW_SRC) | deps
	$(AVR_CC) $(AVR_FLAGS) -I$(B)/avr -Wl,--gc-sections -Wl,--wrap=flood_run bench/avr_flood.c \
	  firmware/explore.c firmware/flood.c firmware/maze.c -o $@
$(B)/avr/tick%.elf: bench/avr_tick.c $(FW_SRC) | deps
	@mkdir -p $(dir $@)
	$(AVR_CC) $(AVR_FLAGS) -DREPS=$* -Wl,--gc-sections bench/avr_tick.c firmware/motion.c firmware/odom.c \
	  firmware/profile.c -lm -o $@
$(B)/bench_flood: bench/bench_flood.c $(B)/libmm.a
	$(CC) $(STD) $(WARN) $(INC) $(CFLAGS) $< $(B)/libmm.a $(LIBS) -o $@

