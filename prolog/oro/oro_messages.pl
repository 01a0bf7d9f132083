:- module(oro_messages, []).

/** <module> Texts of oro's messages

The sentences print_message/2 shows for oro's operator messages
(terms oro(Message)).  Loading this module is enough: it only adds
clauses to the multifile prolog:message//1.
*/

:- multifile
    prolog:message//1.

prolog:message(oro(Message)) -->
    oro_message(Message).

oro_message(ontology_loading(File, Triples, Seconds)) -->
    [ 'oro: loading ~w: ~D triples, ~1f s'-[File, Triples, Seconds] ].
oro_message(ontology_loaded(File, Triples, Seconds)) -->
    [ 'oro: loaded ~w: ~D triples in ~2f s'-[File, Triples, Seconds] ].
