:- module(oro_show,
          [ oro_show/1,                 % +Resource
            oro_show/2,                 % +Model, +Resource
            oro_models/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason), [oro_holds/4]).
:- use_module(library(oro/questions/oro_lookup), [oro_resource_kind/3]).

/** <module> Showing a resource and the models at the toplevel

    ?- oro_show(fork1).
    fork1 (instance) in myself
      labels:     none
      classes:    Fork (asserted); Artifact, Cutlery, owl:Thing (inferred)
      statements:
        fork1 isOn kitchen_table         asserted
        fork1 isAt kitchen_table         inferred

    ?- oro_models.
    model            longterm  shortterm  episodic      mask
    myself                  3          0         0         0
    ontology    577 triples  .../ontologies/commonsense.ttl

Both print on current_output, names contracted as the protocol writes
them (oro_term_light_text/2).  A statement is *asserted* when it is in
the model (one of its memory profiles, or the ontology it did not
remove), *inferred* when only the reasoner gives it.
*/

:- rdf_meta
    oro_show(r),
    oro_show(+, r).

%!  oro_show(+Resource) is det.
%!  oro_show(+Model, +Resource) is det.
%
%   Print what Model (default `myself`) knows of Resource: its kinds,
%   its labels, its classes and the statements whose subject it is
%   (rdf:type and rdfs:label apart), asserted ones first.
%
%   @error existence_error(agent, Model) for an unknown model.
%   @error existence_error(resource, Resource) if no statement of
%   Model mentions Resource as subject.

oro_show(Resource) :-
    oro_show(myself, Resource).

oro_show(Model0, Resource0) :-
    must_be(nonvar, Resource0),
    oro_resolve_model(Model0, Model),
    oro_resource(Resource0, Resource),
    (   oro_holds(Model, Resource, _, _)
    ->  true
    ;   existence_error(resource, Resource)
    ),
    findall(Kind, oro_resource_kind(Model, Resource, Kind), Kinds0),
    sort(Kinds0, Kinds),
    findall(Label, oro_holds(Model, Resource, rdfs:label, Label), Labels0),
    sort(Labels0, Labels),
    findall(Origin-Class,
            ( oro_holds(Model, Resource, rdf:type, Class),
              origin(Model, Resource, rdf:type, Class, Origin)
            ),
            Classes0),
    sort(Classes0, Classes),
    findall(Origin-rdf(Resource, P, O),
            ( oro_holds(Model, Resource, P, O),
              \+ rdf_equal(P, rdf:type),
              \+ rdf_equal(P, rdfs:label),
              origin(Model, Resource, P, O, Origin)
            ),
            Statements0),
    sort(Statements0, Statements),
    show_text(Resource, Name),
    atomic_list_concat(Kinds, ', ', KindText),
    format("~w (~w) in ~w~n", [Name, KindText, Model]),
    show_labels(Labels),
    show_classes(Classes),
    show_statements(Statements).

%   origin(+Model, +S, +P, +O, -Origin): asserted or inferred (the
%   order of the listing).

origin(Model, S, P, O, Origin) :-
    (   oro_asserted(Model, S, P, O)
    ->  Origin = asserted
    ;   Origin = inferred
    ).

show_labels([]) :-
    !,
    format("  labels:     none~n").
show_labels(Labels) :-
    maplist(label_text, Labels, Texts),
    atomic_list_concat(Texts, ', ', Text),
    format("  labels:     ~w~n", [Text]).

label_text(literal(lang(Lang, Lex)), Text) :-
    !,
    format(atom(Text), '"~w"@~w', [Lex, Lang]).
label_text(literal(type(_, Lex)), Text) :-
    !,
    format(atom(Text), '"~w"', [Lex]).
label_text(literal(Lex), Text) :-
    !,
    format(atom(Text), '"~w"', [Lex]).
label_text(Term, Text) :-
    show_text(Term, Text).

show_classes(Classes) :-
    group_pairs_by_key(Classes, Groups),
    findall(Text,
            ( member(Origin-Members, Groups),
              maplist(show_text, Members, Names),
              atomic_list_concat(Names, ', ', List),
              format(atom(Text), '~w (~w)', [List, Origin])
            ),
            Texts),
    (   Texts == []
    ->  format("  classes:    none~n")
    ;   atomic_list_concat(Texts, '; ', Text),
        format("  classes:    ~w~n", [Text])
    ).

show_statements([]) :-
    !,
    format("  statements: none~n").
show_statements(Statements) :-
    format("  statements:~n"),
    forall(member(Origin-rdf(S, P, O), Statements),
           ( maplist(show_text, [S, P, O], Parts),
             atomic_list_concat(Parts, ' ', Text),
             format("    ~w~t~40|  ~w~n", [Text, Origin])
           )).

show_text(Term, Text) :-
    oro_term_light_text(Term, Text).

%!  oro_models is det.
%
%   Print the models with the triples asserted in each of their memory
%   profiles and their mask (the ontology triples they removed), then
%   the ontology files and their triples (oro_store_sizes/1).

oro_models :-
    oro_store_sizes(Sizes),
    Layers = [ profile(longterm), profile(shortterm), profile(episodic),
               mask
             ],
    format("~w~t~16|~t~w~26|~t~w~37|~t~w~47|~t~w~57|~n",
           [model, longterm, shortterm, episodic, mask]),
    findall(Model, ( member(size(Model, _, _), Sizes),
                     Model \== ontology
                   ),
            Models0),
    sort(Models0, Models),
    forall(member(Model, Models),
           ( maplist(layer_size(Sizes, Model), Layers, [L, S, E, M]),
             format("~w~t~16|~t~D~26|~t~D~37|~t~D~47|~t~D~57|~n",
                    [Model, L, S, E, M])
           )),
    forall(member(size(ontology, File, N), Sizes),
           format("ontology~t~16|~t~D~26| triples  ~w~n", [N, File])).

layer_size(Sizes, Model, Layer, N) :-
    (   memberchk(size(Model, Layer, N0), Sizes)
    ->  N = N0
    ;   N = 0
    ).
