:- module(oro,
          [ % setup
            oro_init/1,                 % +Options
            oro_reset/0,
            oro_close/0,
            oro_robot_id/1,             % -Id
            % changes
            oro_add/2,                  % +Model, +Statements
            oro_add/3,                  % +Model, +Statements, +Profile
            oro_remove/2,               % +Model, +Statements
            oro_clear/2,                % +Model, +Patterns
            oro_update/2,               % +Model, +Statements
            oro_update/3,               % +Model, +Statements, +Profile
            oro_save/2,                 % +Model, +File
            % questions
            oro_check/2,                % +Model, +Patterns
            oro_find/4,                 % +Model, ?Var, +Patterns, -Values
            oro_holds/4,                % +Model, ?S, ?P, ?O
            oro_solve/2,                % +Model, +Patterns
            oro_statements/3,           % +Statements, -Triples, -Bindings
            % taxonomy
            oro_type/3,                 % +Model, ?X, ?Class
            oro_subclass/3,             % +Model, ?Sub, ?Super
            oro_subproperty/3,          % +Model, ?Sub, ?Super
            oro_class/2,                % +Model, ?Class
            oro_individual/2,           % +Model, ?X
            oro_superclasses/3,         % +Model, +Class, -Supers
            oro_direct_superclasses/3,  % +Model, +Class, -Supers
            oro_subclasses/3,           % +Model, +Class, -Subs
            oro_direct_subclasses/3,    % +Model, +Class, -Subs
            oro_instances/3,            % +Model, +Class, -Instances
            oro_direct_instances/3,     % +Model, +Class, -Instances
            oro_classes_of/3,           % +Model, +Individual, -Classes
            oro_direct_classes_of/3,    % +Model, +Individual, -Classes
            % labels and descriptions
            oro_exists/2,               % +Model, +Resource
            oro_label/3,                % +Model, +Resource, -Label
            oro_label/4,                % +Model, +Resource, +Lang, -Label
            oro_lookup/3,               % +Model, +Text, -Matches
            oro_resource_kind/3,        % +Model, +Resource, -Kind
            oro_infos/3,                % +Model, +Resource, -Triples
            oro_resource_details/4,     % +Model, +Resource, +Lang, -Details
            % events
            oro_subscribe/7,            % +Model, +Type, +Trigger, +Var, +Patterns, :Callback, -Id
            oro_subscribe/8,            % +Model, +Type, +Trigger, +Var, +Patterns, :Callback, -Subscription, +Options
            oro_unsubscribe/1,          % +IdOrSubscription
            oro_register_event/7,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, -Id
            oro_register_event/8,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, +Registry, -Id
            oro_subscriber_create/3,    % :Deliver, -Subscriber, +Options
            oro_subscriber_destroy/1,   % +Subscriber
            oro_subscriber_destroy/2,   % +Subscriber, +Options
            oro_clear_events/1,         % +Model
            oro_clear_events/2,         % +Model, +Registry
            oro_clear_event/2,          % +Model, +Id
            oro_clear_event/3,          % +Model, +Registry, +Id
            oro_watchers/2,             % +Model, -Watchers
            oro_events_sync/0,
            oro_events_sync_sent/0,
            oro_events_sync_sent/1,     % +Timeout
            % categorization
            oro_similarities/4,         % +Model, +A, +B, -Similarities
            oro_differences/4,          % +Model, +A, +B, -Differences
            oro_common_ancestors/4,     % +Model, +A, +B, -Classes
            oro_discriminate/4,         % +Model, +Individuals, -Total, -Best
            oro_discriminants/3,        % +Model, +Individuals, -Discriminants
            oro_partition/4,            % +Model, +Individuals, +Property, -Partition
            % SPARQL
            oro_sparql/3,               % +Model, +Text, -Result
            oro_sparql/4,               % +Model, +Text, -Result, +Options
            oro_sparql_graph/2,         % ?IRI, ?Graph
            oro_sparql_result_text/3,   % +Format, +Result, -Text
            oro_sparql_json/3,          % +Model, +Text, -JSON
            oro_sparql_parse/2,         % +Text, -Query
            oro_query_values/4,         % +Model, +Key, +Text, -Values
            oro_find/5,                 % +Model, +Var, +Patterns, +Filters, -Values
            oro_sparql_load/0,
            % consistency
            oro_consistent/1,           % +Model
            oro_conflict/2,             % +Model, -Conflict
            oro_consistent_with/2,      % +Model, +Statements
            oro_safe_add/4,             % +Model, +Statements, +Profile, -Accepted
            % explanations
            oro_explain/3,              % +Model, +Statement, -Explanation
            oro_explain_conflict/2,     % +Model, -Conflicts
            oro_explain_conflict/3,     % +Model, +Conflict, -Explanation
            % agents and memory
            oro_agents/1,               % -Names
            oro_create_agent/2,         % +Name, +Individual
            oro_revise/2,               % +Statements, +Policy
            oro_memory_deadlines/2,     % +Model, -Deadlines
            oro_memory_sync/0,
            % concurrency and memory of the store
            oro_store_read/1,           % :Goal
            oro_store_rebuild/0,
            % names
            oro_name_iri/2,             % +Text, -IRI
            oro_iri_name/2,             % +IRI, -Text
            oro_term_text/2,            % +Term, -Text
            oro_rdf11/2,                % +Term, -Rdf11Term
            % toplevel
            oro_show/1,                 % +Resource
            oro_show/2,                 % +Model, +Resource
            oro_models/0,
            op(110, xfx, @),
            op(650, xfx, ^^)
          ]).
%   This library's modules import each other as library(oro/...): when
%   prolog/ is not on the library path yet (a checkout used without
%   installing the pack), put it there.

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.
:- prolog_load_context(directory, Dir),
   (   user:file_search_path(library, Dir)
   ->  true
   ;   asserta(user:file_search_path(library, Dir))
   ).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_knowledge)).
:- use_module(library(oro/oro_setup)).
:- use_module(library(oro/oro_save), [oro_save/2]).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/events/oro_events)).
:- use_module(library(oro/oro_agents)).
:- use_module(library(oro/oro_memory)).
:- use_module(library(oro/questions/oro_consistency)).
:- use_module(library(oro/questions/oro_explain)).
:- use_module(library(oro/questions/oro_categorize)).
:- use_module(library(oro/sparql/oro_sparql)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_query)).
:- use_module(library(oro/questions/oro_taxonomy)).
:- use_module(library(oro/questions/oro_lookup)).
:- use_module(library(oro/oro_store), [oro_store_read/1, oro_store_rebuild/0]).
:- use_module(library(oro/questions/oro_show)).
:- use_module(library(oro/oro_errors), []).

/** <module> oro: a knowledge server for cognitive robots

The public API of oro, usable in-process by planners and from the
toplevel, without any server:

    $ swipl -p library=prolog
    ?- use_module(library(oro)).
    ?- oro_init([]).
    ?- oro_add(myself, ["fork1 rdf:type Fork", "fork1 isOn kitchen_table"]).
    ?- oro_find(myself, o, ["?o isAt kitchen_table"], L).
    L = [oro:fork1].
    ?- oro_type(myself, oro:fork1, C).

Every operation takes the model (agent) first: `myself` (alias
`default`, or the robot id) is the robot.  Statements are text, as the
ORO protocol writes them, or rdf(S,P,O) terms; names may be short
(`fork1`), prefixed (`oro:'Fork'`) or full IRIs.  Loading this module
makes the toplevel print IRIs of known namespaces as `Prefix:Local`,
and oro's errors as sentences (prolog:message//1, oro_errors).

## Literals and library(semweb/rdf11)

An object may be written as rdf11 writes literals, everywhere the API
takes one (statements, patterns, oro_holds/4...): `"x"^^xsd:string`,
`3^^xsd:int`, `true^^xsd:boolean`, `date(2024,1,31)^^xsd:date`,
`"tasse"@fr`, or a plain number (xsd:int or xsd:double) or string
(xsd:string); rdf_db's literal(type(T, Lex)) terms work too.  Answers
are rdf_db terms, as the store holds them; oro_rdf11/2 converts any
answer (a value, a list, triples) to rdf11 terms on request:

    ?- oro_find(myself, w, ["cup1 weight ?w"], L0), oro_rdf11(L0, L).
    L = [150^^'http://www.w3.org/2001/XMLSchema#int'].

This module exports the operators `^^` and `@` as rdf11 does.

## At the toplevel

oro_show/1,2 prints what a model knows of a resource (labels,
classes, statements, asserted and inferred told apart); oro_models/0
lists the models and the size of each of their memory profiles.

The module re-exports the documented predicates of `oro_knowledge`
(changes, check and find), `oro_reason` (the inference closure),
`oro_taxonomy`, `oro_lookup` and `oro_names`.
*/

:- multifile user:portray/1.

%   Print IRIs of the namespaces oro knows as Prefix:Local, so answers
%   read like what was typed.

user:portray(IRI) :-
    atom(IRI),
    sub_atom(IRI, 0, _, _, http),
    oro_prefix(Prefix, NS),
    atom_concat(NS, Local, IRI),
    Local \== '',
    format('~q', [Prefix:Local]).
