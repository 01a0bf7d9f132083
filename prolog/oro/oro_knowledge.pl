:- module(oro_knowledge,
          [ oro_add/2,                  % +Model, +Statements
            oro_add/3,                  % +Model, +Statements, +Profile
            oro_remove/2,               % +Model, +Statements
            oro_clear/2,                % +Model, +Patterns
            oro_update/2,               % +Model, +Statements
            oro_update/3,               % +Model, +Statements, +Profile
            oro_check/2,                % +Model, +Patterns
            oro_find/4,                 % +Model, ?Var, +Patterns, -Values
            oro_robot_id/1,             % -Id
            oro_create_robot_model/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_query)).
:- use_module(library(oro/events/oro_events)).
:- use_module(library(oro/oro_memory)).
:- use_module(library(oro/oro_save)).

/** <module> Knowledge operations: add, remove, clear, update, check, find

The operations of ORO's base methods, on a model (agent) given first:
`myself` (or `default`, or the robot id) is the robot.  Statements and
patterns are given either as text, exactly as over the protocol
(`"fork1 isOn kitchen_table"`, `"?o isAt kitchen_table"`), or as terms
rdf(S, P, O) whose names may be short (`fork1`), prefixed
(`oro:'Fork'`, `rdf:type`) or full IRIs, whose objects may be Prolog
numbers or strings (typed literals) or rdf_db literal terms, and whose
variables are Prolog variables.

    ?- oro_init([]),                % library(oro/oro_setup)
       oro_add(myself, ["fork1 rdf:type Fork", "fork1 isOn kitchen_table"]),
       oro_find(myself, o, ["?o isAt kitchen_table"], L).
    L = ['http://kb.openrobots.org#fork1'].

Every change is one transaction: a batch is applied whole or not at
all, and a malformed statement anywhere rejects the batch before
anything changes.
*/

:- setting(robot_id, atom, '',
           'Id of the robot: a synonym of myself (empty: none)').

%!  oro_create_robot_model is det.
%
%   Create the robot's model, `myself` (alias `default` and the robot
%   id), with the robot's own facts.

oro_create_robot_model :-
    oro_create_model(myself),
    oro_add_model_alias(default, myself),
    oro_robot_id(RobotId),
    (   RobotId == ''
    ->  Facts = ["myself rdf:type Robot"]
    ;   oro_add_model_alias(RobotId, myself),
        format(string(SameAs), "myself owl:sameAs ~w", [RobotId]),
        Facts = ["myself rdf:type Robot", SameAs]
    ),
    oro_add(myself, Facts).

%!  oro_robot_id(-Id) is det.
%
%   The robot id given to oro_init/1, or '' if none.

oro_robot_id(Id) :-
    setting(robot_id, Id).

		 /*******************************
		 *          CHANGES             *
		 *******************************/

%!  oro_add(+Model, +Statements) is det.
%
%   Assert Statements (long-term memory) in Model, in one transaction.
%   Statements already known are ignored.  No consistency check.
%
%   @error existence_error(agent, Model) for an unknown model.
%   @error syntax_error(_) if a statement is malformed or incomplete;
%          nothing is then changed.

oro_add(Model, Statements) :-
    oro_add(Model, Statements, longterm).

%!  oro_add(+Model, +Statements, +Profile) is det.
%
%   Assert Statements in Model with the memory Profile: `longterm`
%   (also `default`: never forgotten), `shortterm` or `episodic` (see
%   oro_memory); names in any case, unknown ones meaning `longterm`.

oro_add(Model0, Statements, Profile0) :-
    oro_resolve_model(Model0, Model),
    oro_memory_profile(Profile0, Profile),
    oro_complete_statements(Statements, Triples),
    oro_store_write(add(Model), add_triples(Model, Triples, Profile)).

add_triples(Model, Triples, Profile) :-
    oro_store_assert(Model, Triples, Profile),
    oro_memory_remember(Model, Profile, Triples).

%!  oro_remove(+Model, +Statements) is det.
%
%   Retract Statements from Model.  A statement with variables is a
%   pattern, as in oro_clear/2.  Unknown statements are ignored.

oro_remove(Model, Statements) :-
    oro_clear(Model, Statements).

%!  oro_clear(+Model, +Patterns) is det.
%
%   Retract, in one transaction, every *asserted* statement of Model
%   matching one of Patterns.  Patterns are independent (their
%   variables are not shared): `gorilla ?p ?o` forgets everything
%   asserted about gorilla.  Inferred statements cannot be retracted;
%   retract what supports them.

oro_clear(Model0, Patterns) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Patterns),
    maplist(pattern_triple, Patterns, Triples),
    oro_store_write(clear(Model), clear_triples(Model, Triples)).

pattern_triple(Pattern, Triple) :-
    oro_statements([Pattern], [Triple], _).

clear_triples(Model, Patterns) :-
    findall(Match,
            ( member(Pattern, Patterns),
              asserted_match(Model, Pattern, Match)
            ),
            Matches0),
    sort(Matches0, Matches),
    oro_store_retract(Model, Matches).

%   asserted_match(+Model, +Pattern, -Triple): Triple is an asserted
%   triple matching Pattern, literals compared by value.

asserted_match(Model, rdf(S, P, O), rdf(S, P, Stored)) :-
    (   nonvar(O),
        O = literal(_)
    ->  oro_asserted(Model, S, P, Stored),
        Stored = literal(_),
        oro_literal_match(O, Stored)
    ;   Stored = O,
        oro_asserted(Model, S, P, Stored)
    ).

%!  oro_update(+Model, +Statements) is det.
%
%   Like oro_add/2, but for each statement whose predicate is a
%   functional property of Model (declared in the ontology or at run
%   time), first retract the asserted values it had for that subject.

oro_update(Model, Statements) :-
    oro_update(Model, Statements, longterm).

%!  oro_update(+Model, +Statements, +Profile) is det.
%
%   As oro_update/2, the statements being asserted with the memory
%   Profile as oro_add/3 takes it (lifespan(Units) too).

oro_update(Model0, Statements, Profile0) :-
    oro_resolve_model(Model0, Model),
    oro_memory_profile(Profile0, Profile),
    oro_complete_statements(Statements, Triples),
    oro_store_write(update(Model), update_triples(Model, Triples, Profile)).

update_triples(Model, Triples, Profile) :-
    findall(rdf(S, P, Old),
            ( member(rdf(S, P, _), Triples),
              oro_functional_property(Model, P),
              oro_asserted(Model, S, P, Old)
            ),
            Stale0),
    sort(Stale0, Stale),
    oro_store_retract(Model, Stale),
    add_triples(Model, Triples, Profile).

		 /*******************************
		 *          QUESTIONS           *
		 *******************************/

%!  oro_check(+Model, +Patterns) is semidet.
%
%   True if every pattern holds in the inference closure of Model.  A
%   complete statement must be entailed; a partial one must have a
%   solution.  Patterns do not share variables.

oro_check(Model0, Patterns) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Patterns),
    maplist(pattern_triple, Patterns, Triples),
    forall(member(Triple, Triples),
           oro_pattern_holds(Model, Triple)).

%!  oro_find(+Model, ?Var, +Patterns, -Values) is det.
%
%   Values is the ordered set of the values Var takes over the
%   solutions of Patterns (a conjunction sharing variables) in the
%   inference closure of Model; blank nodes are left out.  With text
%   patterns, Var is a variable name (`o` or `?o`); with term patterns
%   it is a Prolog variable (or a term of them) of Patterns.  A name
%   that no pattern uses gives `[]`.
%
%   @error domain_error(oro_variable, '') for an empty variable name.
%   @error resource_error(oro_query_time_limit(Seconds)) past the
%          `oro_query:time_limit` setting, for a join of two patterns
%          or more.

oro_find(Model0, Var, Patterns, Values) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Patterns),
    oro_statements(Patterns, Triples, Bindings),
    (   text(Var)
    ->  variable_name(Var, Name),
        (   memberchk(Name=Template, Bindings)
        ->  oro_find_values(Model, Template, Triples, Values)
        ;   Values = []
        )
    ;   oro_find_values(Model, Var, Triples, Values)
    ).

text(X) :-
    (   string(X)
    ->  true
    ;   atom(X)
    ).

variable_name(Text, Name) :-
    atom_string(Atom, Text),
    (   sub_atom(Atom, 0, 1, _, ?)
    ->  sub_atom(Atom, 1, _, 0, Name0)
    ;   Name0 = Atom
    ),
    normalize_space(atom(Name), Name0),
    (   Name == ''
    ->  domain_error(oro_variable, Text)
    ;   true
    ).
