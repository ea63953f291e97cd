# docs.mk - make docs: the figures and pictures the docs show, from the code.

# The figures and pictures the docs show, written by the programs that make
# them: docs/VALIDATION.md's --validate tables (tools/docs-validation;
# test/cli/cli_validate.sh checks them) and the README's three pictures with the
# README's commands (docs-img, into IMG_DIR; without a display under
# xvfb-run; test/cli/cli_docs_img.sh checks them)
.PHONY: docs
docs: $(B)/mmsim $(B)/mmview
	python3 tools/docs-validation --mmsim $(B)/mmsim
	@$(MAKE) --no-print-directory docs-img


IMG_DIR ?= docs/img
docs-img: $(B)/mmsim $(B)/mmview
	@bash tools/make/docs-img.sh $(B)/mmsim $(B)/mmview $(IMG_DIR)
